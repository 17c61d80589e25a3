// Parsing an empty input must give exactly the default-constructed
// Parameters.  The entries of a ParameterTable take their defaults from the
// member initializers (so this checks prm_string()'s round trip and the
// tables' member pointers); the few entries declared by hand beside the
// tables (lists, `auto` or a number, 'same' or a number) are checked
// against their members here.  Every member is compared, without a hand-written list: the
// structs are aggregates, so their members are counted (the largest N
// with which T{x_1, ..., x_N} compiles, as Boost.PFR does) and visited
// with structured bindings, recursively into nested structs and vectors.
// A member added to any Parameters struct is compared automatically.

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/problem/parameters.h>

#include <cstdio>
#include <cxxabi.h>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

namespace fgimpact_unit_tests::parameters_defaults
{

  using namespace fgimpact;

  namespace
  {
    /// Converts to any member type (never called: unevaluated only).
    struct AnyField
    {
      template <typename T>
      constexpr
      operator T &() const &&noexcept;
    };

    template <std::size_t>
    using any_field = AnyField;

    template <typename T, typename Indices, typename = void>
    struct BraceConstructible : std::false_type
    {};

    template <typename T, std::size_t... I>
    struct BraceConstructible<T,
                              std::index_sequence<I...>,
                              std::void_t<decltype(T{any_field<I>{}...})>>
      : std::true_type
    {};

    /// The number of members of the aggregate T (at most 32; 33 means more).
    template <typename T, std::size_t N = 33>
    constexpr std::size_t
    n_fields()
    {
      if constexpr (N == 0)
        return 0;
      else if constexpr (BraceConstructible<T,
                                            std::make_index_sequence<N>>::value)
        return N;
      else
        return n_fields<T, N - 1>();
    }

    /// f(index, x's member, y's member) for every member of x and y.
    template <std::size_t N, typename T, typename F>
    void
    for_each_field(const T &x, const T &y, const F &f)
    {
      static_assert(N > 0 && N <= 32, "extend the ladder below");
      // clang-format off
    if constexpr (N == 1) { const auto &[a0] = x; const auto &[b0] = y; f(0, a0, b0); }
    else if constexpr (N == 2) { const auto &[a0, a1] = x; const auto &[b0, b1] = y; f(0, a0, b0); f(1, a1, b1); }
    else if constexpr (N == 3) { const auto &[a0, a1, a2] = x; const auto &[b0, b1, b2] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); }
    else if constexpr (N == 4) { const auto &[a0, a1, a2, a3] = x; const auto &[b0, b1, b2, b3] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); }
    else if constexpr (N == 5) { const auto &[a0, a1, a2, a3, a4] = x; const auto &[b0, b1, b2, b3, b4] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); }
    else if constexpr (N == 6) { const auto &[a0, a1, a2, a3, a4, a5] = x; const auto &[b0, b1, b2, b3, b4, b5] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); }
    else if constexpr (N == 7) { const auto &[a0, a1, a2, a3, a4, a5, a6] = x; const auto &[b0, b1, b2, b3, b4, b5, b6] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); }
    else if constexpr (N == 8) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); }
    else if constexpr (N == 9) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); }
    else if constexpr (N == 10) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); }
    else if constexpr (N == 11) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); }
    else if constexpr (N == 12) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); }
    else if constexpr (N == 13) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); }
    else if constexpr (N == 14) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); }
    else if constexpr (N == 15) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); }
    else if constexpr (N == 16) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); }
    else if constexpr (N == 17) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); }
    else if constexpr (N == 18) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); }
    else if constexpr (N == 19) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); }
    else if constexpr (N == 20) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); }
    else if constexpr (N == 21) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); }
    else if constexpr (N == 22) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); }
    else if constexpr (N == 23) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); }
    else if constexpr (N == 24) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); }
    else if constexpr (N == 25) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); }
    else if constexpr (N == 26) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24, a25] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24, b25] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); f(25, a25, b25); }
    else if constexpr (N == 27) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24, a25, a26] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24, b25, b26] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); f(25, a25, b25); f(26, a26, b26); }
    else if constexpr (N == 28) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24, a25, a26, a27] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24, b25, b26, b27] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); f(25, a25, b25); f(26, a26, b26); f(27, a27, b27); }
    else if constexpr (N == 29) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24, a25, a26, a27, a28] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24, b25, b26, b27, b28] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); f(25, a25, b25); f(26, a26, b26); f(27, a27, b27); f(28, a28, b28); }
    else if constexpr (N == 30) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24, a25, a26, a27, a28, a29] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24, b25, b26, b27, b28, b29] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); f(25, a25, b25); f(26, a26, b26); f(27, a27, b27); f(28, a28, b28); f(29, a29, b29); }
    else if constexpr (N == 31) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24, a25, a26, a27, a28, a29, a30] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24, b25, b26, b27, b28, b29, b30] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); f(25, a25, b25); f(26, a26, b26); f(27, a27, b27); f(28, a28, b28); f(29, a29, b29); f(30, a30, b30); }
    else if constexpr (N == 32) { const auto &[a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23, a24, a25, a26, a27, a28, a29, a30, a31] = x; const auto &[b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11, b12, b13, b14, b15, b16, b17, b18, b19, b20, b21, b22, b23, b24, b25, b26, b27, b28, b29, b30, b31] = y; f(0, a0, b0); f(1, a1, b1); f(2, a2, b2); f(3, a3, b3); f(4, a4, b4); f(5, a5, b5); f(6, a6, b6); f(7, a7, b7); f(8, a8, b8); f(9, a9, b9); f(10, a10, b10); f(11, a11, b11); f(12, a12, b12); f(13, a13, b13); f(14, a14, b14); f(15, a15, b15); f(16, a16, b16); f(17, a17, b17); f(18, a18, b18); f(19, a19, b19); f(20, a20, b20); f(21, a21, b21); f(22, a22, b22); f(23, a23, b23); f(24, a24, b24); f(25, a25, b25); f(26, a26, b26); f(27, a27, b27); f(28, a28, b28); f(29, a29, b29); f(30, a30, b30); f(31, a31, b31); }
      // clang-format on
    }

    template <typename T>
    struct IsVector : std::false_type
    {};
    template <typename E, typename A>
    struct IsVector<std::vector<E, A>> : std::true_type
    {};

    template <typename T, typename = void>
    struct EqualityComparable : std::false_type
    {};
    template <typename T>
    struct EqualityComparable<T,
                              std::void_t<decltype(std::declval<const T &>() ==
                                                   std::declval<const T &>())>>
      : std::true_type
    {};

    std::string
    type_name(const std::type_info &type)
    {
      int   status = 0;
      char *name = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
      std::string result = (status == 0 ? name : type.name());
      std::free(name);
      return result;
    }

    unsigned int n_compared = 0, n_different = 0, n_structs = 0;

    /// Compare x and y member by member; path: the members' indices.
    template <typename T>
    void
    compare(const std::string &path, const T &x, const T &y)
    {
      if constexpr (IsVector<T>::value)
        {
          if (x.size() != y.size())
            {
              ++n_compared;
              ++n_different;
              std::printf("DIFFERENT: %s (%s, sizes)\n",
                          path.c_str(),
                          type_name(typeid(T)).c_str());
              return;
            }
          for (std::size_t i = 0; i < x.size(); ++i)
            compare(path + "[" + std::to_string(i) + "]", x[i], y[i]);
        }
      else if constexpr (std::is_aggregate_v<T> && std::is_class_v<T>)
        {
          ++n_structs;
          for_each_field<n_fields<T>()>(
            x, y, [&](const std::size_t i, const auto &a, const auto &b) {
              compare(path + "." + std::to_string(i), a, b);
            });
        }
      else
        {
          static_assert(EqualityComparable<T>::value,
                        "a Parameters member that is neither an aggregate, a "
                        "vector nor comparable with ==");
          ++n_compared;
          if (!(x == y))
            {
              ++n_different;
              std::printf("DIFFERENT: %s (%s)\n",
                          path.c_str(),
                          type_name(typeid(T)).c_str());
            }
        }
    }
  } // namespace

  int
  test_main(int, char **)
  {
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.parse_input_from_string("");
    Parameters parsed;
    parsed.parse_parameters(prm);
    const Parameters initialized;

    static_assert(n_fields<Parameters>() >= 13, "the member count failed");
    compare("Parameters", parsed, initialized);
    // 66 members were compared by a hand-written list before.
    std::printf("%u structs visited, %u members compared, %u different\n",
                n_structs,
                n_compared,
                n_different);
    std::printf(n_different == 0 ? "all checks passed\n" : "CHECK FAILED\n");
    return n_different == 0 ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::parameters_defaults
