// ParameterTable (base/parameter_table.h): each entry's default is its
// member's initializer, written back by prm_string().  Checks: prm_string()
// gives the expected strings for hand-picked values and reads back as the
// same double for 200000 values over 600 decades; a table's declared
// defaults parse into the default-constructed struct, and set values land
// in their members (each type: double, unsigned, int, bool, string,
// selection).

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/base/parameter_table.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

namespace fgimpact_unit_tests::parameter_table
{
  using namespace fgimpact;

  namespace
  {
    enum class Colour
    {
      red,
      blue
    };

    const SelectionTable<Colour> &
    colour_names()
    {
      static const SelectionTable<Colour> names = {{"red", Colour::red},
                                                   {"blue", Colour::blue}};
      return names;
    }

    struct Toy
    {
      double       modulus = 70e9;
      unsigned int levels  = 3;
      int          offset  = -2;
      bool         flag    = true;
      std::string  file    = "a.csv";
      Colour       colour  = Colour::blue;
    };

    const ParameterTable<Toy> &
    toy_table()
    {
      static const ParameterTable<Toy> table = [] {
        ParameterTable<Toy> t;
        t.add("Modulus", &Toy::modulus, Patterns::Double(0, 1e15), "Pa.");
        t.add("Levels", &Toy::levels, Patterns::Integer(0, 9), "levels.");
        t.add("Offset", &Toy::offset, Patterns::Integer(-9, 9), "offset.");
        t.add("Flag", &Toy::flag, Patterns::Bool(), "flag.");
        t.add("File", &Toy::file, Patterns::Anything(), "file.");
        t.add("Colour", &Toy::colour, colour_names(), "colour.");
        return t;
      }();
      return table;
    }

    bool
    same(const Toy &a, const Toy &b)
    {
      return a.modulus == b.modulus && a.levels == b.levels &&
             a.offset == b.offset && a.flag == b.flag && a.file == b.file &&
             a.colour == b.colour;
    }
  } // namespace



  int
  test_main(int, char **)
  {
    bool ok = true;

    const std::pair<double, const char *> hand[] = {{0.2, "0.2"},
                                                    {70e9, "70e9"},
                                                    {380e9, "380e9"},
                                                    {2707., "2707"},
                                                    {1e-6, "1e-6"},
                                                    {2.5e-5, "25e-6"},
                                                    {-3e7, "-30e6"},
                                                    {3e8, "3e8"},
                                                    {1e-10, "1e-10"},
                                                    {1e6, "1e6"},
                                                    {1e-4, "0.0001"},
                                                    {0., "0"},
                                                    {123456.5, "123456.5"}};
    for (const auto &[value, expected] : hand)
      {
        const std::string text = prm_string(value);
        const bool        pass = text == expected;
        ok                     = ok && pass;
        std::printf("prm_string: %-10s %s\n",
                    expected,
                    pass ? "as expected" : ("GOT " + text).c_str());
      }

    // Any double reads back exactly (mantissa random, exponent -300..300).
    std::mt19937                           random(42);
    std::uniform_real_distribution<double> mantissa(-10., 10.);
    std::uniform_int_distribution<int>     exponent(-300, 300);
    unsigned int                           mismatches = 0;
    for (unsigned int k = 0; k < 200000; ++k)
      {
        const double x = mantissa(random) * std::pow(10., exponent(random));
        if (std::strtod(prm_string(x).c_str(), nullptr) != x)
          ++mismatches;
      }
    ok = ok && mismatches == 0;
    std::printf("200000 doubles written and read back: %u differ\n",
                mismatches);

    // Declared defaults = the default-constructed struct.
    ParameterHandler prm;
    toy_table().declare(prm);
    Toy parsed;
    parsed.modulus = 0;
    parsed.colour  = Colour::red;
    toy_table().parse(prm, parsed);
    const bool defaults_ok = same(parsed, Toy());
    ok                     = ok && defaults_ok;
    std::printf("defaults parsed: %s\n",
                defaults_ok ? "the struct's initializers" : "DIFFERENT");

    // Set values land in their members.
    prm.set("Modulus", "210e9");
    prm.set("Levels", "7");
    prm.set("Offset", "4");
    prm.set("Flag", "false");
    prm.set("File", "b.csv");
    prm.set("Colour", "red");
    toy_table().parse(prm, parsed);
    const Toy  expected{210e9, 7, 4, false, "b.csv", Colour::red};
    const bool set_ok = same(parsed, expected);
    ok                = ok && set_ok;
    std::printf("set values parsed: %s\n",
                set_ok ? "in their members" : "WRONG");

    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::parameter_table
