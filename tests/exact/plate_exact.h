// Exact 3D-elasticity reference solutions for simply supported rectangular
// plates whose isotropic material varies through the thickness.
//
// Independent of the fgimpact library: only the C++ standard library and
// Eigen are used. It is meant as a test oracle for the finite element code:
// a static sinusoidal-pressure solution and the natural frequencies of the
// plate, both exact up to the numerical integration of an ODE in z. The
// integration is of 4th order; with the default 256 sub-layers the static
// deflection and the fundamental frequency of the paper's n = 1 and n = 5
// plates are accurate to 2e-11 and 2e-10 relative (against 1024 sub-layers
// and an independent Chebyshev solution, navier_chebyshev_check.py);
// homogeneous plates are integrated exactly (constant A).
//
// ---------------------------------------------------------------------------
// Problem and derivation
// ---------------------------------------------------------------------------
// Plate 0 <= x <= a, 0 <= y <= b, 0 <= z <= h (z from the bottom face).
// The material is isotropic at each z: Young's modulus E(z), density rho(z),
// Poisson's ratio nu(z) (constant, or a profile Plate::nu_z), so that
//   lambda(z) = E nu / ((1 + nu)(1 - 2 nu)),   mu(z) = E / (2 (1 + nu)).
// The four side faces are simply supported: w = 0, the tangential in-plane
// displacement = 0 and the normal stress = 0 on the whole face (v = 0,
// sigma_xx = 0 on x = 0, a; u = 0, sigma_yy = 0 on y = 0, b).
//
// With p = m pi / a, q = n pi / b the problem separates exactly:
//   u = U(z) cos(px) sin(qy),  v = V(z) sin(px) cos(qy),
//   w = W(z) sin(px) sin(qy),
//   sigma_xz = X(z) cos sin,   sigma_yz = Y(z) sin cos,
//   sigma_zz = Z(z) sin sin,
//   sigma_xx = Sxx(z) sin sin, sigma_yy = Syy(z) sin sin,
//   sigma_xy = Sxy(z) cos cos,
// which satisfies every side-face condition term by term.
// Strains (d/dx cos(px) = -p sin(px), d/dx sin(px) = p cos(px)):
//   e_xx = -p U ss, e_yy = -q V ss, e_zz = W' ss,
//   g_xy = (q U + p V) cc, g_xz = (U' + p W) cs, g_yz = (V' + q W) sc.
// Hooke's law for the z-components gives the first three rows:
//   X = mu (U' + p W)                    =>  U' = -p W + X / mu
//   Y = mu (V' + q W)                    =>  V' = -q W + Y / mu
//   Z = -lambda (p U + q V) + (lambda + 2 mu) W'
//                                        =>  W' = beta (p U + q V) + Z / C33
// with C33 = lambda + 2 mu = E (1 - nu) / ((1 + nu)(1 - 2 nu)) and
// beta = lambda / C33 = nu / (1 - nu). Eliminating W' from the in-plane
// stresses (Q11 = E / (1 - nu^2), Q12 = nu Q11):
//   Sxx = -Q11 p U - Q12 q V + beta Z,
//   Syy = -Q12 p U - Q11 q V + beta Z,
//   Sxy = mu (q U + p V).
// The equations of motion sigma_ij,j = -rho omega^2 u_i (harmonic motion,
// omega = 0 for statics) give the last three rows:
//   x: p Sxx - q Sxy + X' = -rho w^2 U
//        =>  X' = (Q11 p^2 + mu q^2 - rho w^2) U + (Q12 + mu) p q V - beta p Z
//   y: -p Sxy + q Syy + Y' = -rho w^2 V
//        =>  Y' = (Q12 + mu) p q U + (Q11 q^2 + mu p^2 - rho w^2) V - beta q Z
//   z: -p X - q Y + Z' = -rho w^2 W
//        =>  Z' = -rho w^2 W + p X + q Y
// So d/dz [U V W X Y Z]^T = A(z; omega) [U V W X Y Z]^T with
//
//        |  0                   0                   -p        1/mu  0     0      |
//        |  0                   0                   -q        0     1/mu  0      |
//   A =  |  beta p              beta q               0        0     0     1/C33  |
//        |  Q11 p^2+mu q^2-rw2  (Q12+mu) p q         0        0     0    -beta p |
//        |  (Q12+mu) p q        Q11 q^2+mu p^2-rw2   0        0     0    -beta q |
//        |  0                   0                   -rw2      p     q     0      |
//
// (rw2 = rho(z) omega^2). No derivative of E(z) or nu(z) appears (every
// entry is a local value: Q11, Q12, mu, C33 and beta all at the same z), so
// the formulation is valid for any piecewise continuous gradation of E, nu
// and rho alike. Traction conditions on
// the faces: X = Y = 0 at z = 0 and z = h, and Z(0) = 0, Z(h) = -q0 for a
// downward pressure q0 sin(px) sin(qy) on the top face, or Z = 0 on both
// faces for free vibration. W is positive upward (along +z); a downward
// deflection is -W.
//
// Two exact sub-structures are used by the tests: (i) the in-plane
// components L = (p U + q V) / k and T = (q U - p V) / k (k^2 = p^2 + q^2)
// split off an exactly decoupled "in-plane shear" (SH) system
//   T' = S / mu,  S' = (mu k^2 - rho omega^2) T,  S = (q X - p Y) / k,
// with W = L = 0; for a homogeneous plate its lowest mode has T uniform and
// omega = k sqrt(mu / rho). (ii) The remaining 4x4 sagittal system carries
// the flexural, extensional and thickness modes (Rayleigh-Lamb modes for a
// homogeneous plate).
//
// ---------------------------------------------------------------------------
// Numerics
// ---------------------------------------------------------------------------
// The state is non-dimensionalised internally (zeta = z / h, displacements
// / h, stresses / E(h/2)), so all entries of A are O(1). The 6x6 transfer
// matrix T (y(h) = T y(0)) is the product over sub-layers
// [zeta_i, zeta_{i+1}], zeta_i = (i / N)^grading, of exp(Omega_i) with the
// fourth-order Magnus (Gauss-Legendre) approximation
//   Omega = d/2 (A1 + A2) + sqrt(3) d^2 / 12 [A2, A1],
//   A_{1,2} = A(zeta_i + d (1/2 -+ sqrt(3)/6)),  d = zeta_{i+1} - zeta_i,
// exact for constant A (homogeneous layers). exp() is a scaled and squared
// Taylor series. With y(0) = [U0 V0 W0 0 0 0], the top tractions are
// T21 [U0 V0 W0] (T21 = lower-left 3x3 block): statics solve
// T21 u0 = [0 0 -q0], and natural frequencies are the zeros of
// f(omega) = det T21(omega). T depends on omega^2 polynomially within each
// layer, so f is an entire function of omega: it has no poles and changes
// sign at every simple root. The roots are bracketed on a uniform omega grid
// starting at omega = 0 (f(0) != 0, the static problem being regular) and
// refined by Brent's method. Two roots closer than one grid step (e.g. the
// nearly degenerate lowest flexural/extensional pair when k h >> 1) or a
// double root can be missed: refine Options::scan_points when in doubt.
// For a power law with a non-integer index the profile is not smooth at
// z = 0; use Options::grading > 1 (sub-layers clustered at the bottom).

#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fgimpact_exact
{
  /// A through-the-thickness material profile P(z), 0 <= z <= h.
  using Profile = std::function<double(double)>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  // ------------------------------------------------------------------------
  // Material helpers
  // ------------------------------------------------------------------------

  /// A profile that is the same at every z.
  inline Profile
  constant_profile(const double value)
  {
    return [value](double) { return value; };
  }

  /// The paper's power law (Eq. 2.1), metal on top, z from the bottom face:
  ///   P(z) = P_c + (P_m - P_c) (z / h)^index.
  /// index = 0 gives pure metal (std::pow(0, 0) = 1), large index tends to
  /// pure ceramic.
  inline Profile
  power_law_profile(const double metal,
                    const double ceramic,
                    const double index,
                    const double h)
  {
    return [=](const double z) {
      return ceramic + (metal - ceramic) * std::pow(z / h, index);
    };
  }

  /// Everything that defines the plate (geometry, profiles, Poisson ratio).
  struct Plate
  {
    Profile E;
    Profile rho;
    double  nu = 0.3;
    double  a  = 0.2;
    double  b  = 0.1;
    double  h  = 0.02;
    /// Poisson's ratio through the thickness; empty: the constant nu.
    Profile nu_z = Profile();

    /// nu at height z.
    double
    poisson(const double z) const
    {
      return nu_z ? nu_z(z) : nu;
    }
  };

  /// The paper's FGM plate in one line: power law (Eq. 2.1) for E and rho
  /// with the paper's default constituents and dimensions.
  inline Plate
  power_law_plate(const double index,
                  const double a       = 0.2,
                  const double b       = 0.1,
                  const double h       = 0.02,
                  const double E_m     = 70e9,
                  const double rho_m   = 2707.,
                  const double E_c     = 380e9,
                  const double rho_c   = 3800.,
                  const double nu      = 0.3)
  {
    return Plate{power_law_profile(E_m, E_c, index, h),
                 power_law_profile(rho_m, rho_c, index, h),
                 nu,
                 a,
                 b,
                 h};
  }

  /// A homogeneous plate (defaults: the paper's metal and dimensions).
  inline Plate
  homogeneous_plate(const double E   = 70e9,
                    const double rho = 2707.,
                    const double nu  = 0.3,
                    const double a   = 0.2,
                    const double b   = 0.1,
                    const double h   = 0.02)
  {
    return Plate{constant_profile(E), constant_profile(rho), nu, a, b, h};
  }

  /// Numerical parameters of the thickness integration and the root search.
  struct Options
  {
    /// Number of sub-layers (fourth-order Magnus steps) over the thickness.
    unsigned int layers = 256;
    /// Sub-layer boundaries z_i = h (i / layers)^grading.
    double grading = 1.;
    /// Frequency scan: grid points per omega_unit = c_T,min min(k, pi / h)
    /// (c_T,min = smallest shear wave speed). Larger is safer and slower.
    double scan_points = 100.;
    /// Upper end of an open-ended scan in units of omega_unit.
    double scan_limit = 1000.;
  };

  namespace internal
  {
    /// exp(A) by scaling and squaring of a Taylor series.
    inline Matrix6
    expm(const Matrix6 &A)
    {
      const double norm = A.cwiseAbs().rowwise().sum().maxCoeff();
      int          s    = 0;
      if (norm > 0.5)
        s = static_cast<int>(std::ceil(std::log2(norm / 0.5)));
      const Matrix6 B      = A / std::ldexp(1., s);
      Matrix6       result = Matrix6::Identity();
      Matrix6       term   = Matrix6::Identity();
      for (int j = 1; j <= 40; ++j)
        {
          term = term * B / j;
          result += term;
          if (term.cwiseAbs().maxCoeff() <=
              1e-18 * result.cwiseAbs().maxCoeff())
            break;
        }
      for (int i = 0; i < s; ++i)
        result = result * result;
      return result;
    }

    /// Brent's method on [x0, x1] with f(x0) f(x1) <= 0.
    template <typename F>
    double
    brent(const F &f, double x0, double x1, double f0, double f1)
    {
      if (f0 == 0.)
        return x0;
      if (f1 == 0.)
        return x1;
      double a = x0, b = x1, fa = f0, fb = f1;
      double c = a, fc = fa, d = b - a, e = d;
      for (int iter = 0; iter < 200; ++iter)
        {
          if ((fb > 0.) == (fc > 0.))
            {
              c  = a;
              fc = fa;
              d = e = b - a;
            }
          if (std::abs(fc) < std::abs(fb))
            {
              a  = b;
              b  = c;
              c  = a;
              fa = fb;
              fb = fc;
              fc = fa;
            }
          const double tol =
            2. * std::numeric_limits<double>::epsilon() * std::abs(b);
          const double xm = 0.5 * (c - b);
          if (std::abs(xm) <= tol || fb == 0.)
            return b;
          if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb))
            {
              double       p, q;
              const double s = fb / fa;
              if (a == c)
                {
                  p = 2. * xm * s;
                  q = 1. - s;
                }
              else
                {
                  const double qq = fa / fc, r = fb / fc;
                  p = s * (2. * xm * qq * (qq - r) - (b - a) * (r - 1.));
                  q = (qq - 1.) * (r - 1.) * (s - 1.);
                }
              if (p > 0.)
                q = -q;
              p = std::abs(p);
              if (2. * p < std::min(3. * xm * q - std::abs(tol * q),
                                    std::abs(e * q)))
                {
                  e = d;
                  d = p / q;
                }
              else
                {
                  d = xm;
                  e = d;
                }
            }
          else
            {
              d = xm;
              e = d;
            }
          a  = b;
          fa = fb;
          b += (std::abs(d) > tol) ? d : (xm > 0. ? tol : -tol);
          fb = f(b);
        }
      return b;
    }

    /// The non-dimensional thickness problem of one mode (m, n).
    class ThicknessProblem
    {
    public:
      ThicknessProblem(const Plate       &plate,
                       const unsigned int m,
                       const unsigned int n,
                       const Options     &options)
        : plate(plate)
        , options(options)
        , p(m * M_PI / plate.a)
        , q(n * M_PI / plate.b)
        , k(std::hypot(p, q))
      {
        if (m == 0 || n == 0)
          throw std::invalid_argument("mode numbers must be >= 1");
        if (!(plate.h > 0. && plate.a > 0. && plate.b > 0.) ||
            options.layers == 0 || !(options.grading > 0.))
          throw std::invalid_argument("bad plate geometry or options");
        E0 = plate.E(0.5 * plate.h);
        if (!(E0 > 0.))
          throw std::invalid_argument("E(h/2) must be positive");
        const unsigned int N = options.layers;
        nodes.resize(N + 1);
        for (unsigned int i = 0; i <= N; ++i)
          nodes[i] = std::pow(double(i) / N, options.grading);
        nodes[N] = 1.;
        // Material data at the two Gauss points of every sub-layer.
        c_T_min = std::numeric_limits<double>::max();
        layer_A.resize(2 * N);
        layer_rho.resize(2 * N);
        for (unsigned int i = 0; i < N; ++i)
          for (unsigned int g = 0; g < 2; ++g)
            {
              const double zeta = gauss_point(nodes[i], nodes[i + 1], g);
              layer_A[2 * i + g]   = static_matrix(zeta);
              layer_rho[2 * i + g] = plate.rho(zeta * plate.h);
              const double mu =
                plate.E(zeta * plate.h) /
                (2. * (1. + plate.poisson(zeta * plate.h)));
              c_T_min = std::min(c_T_min, std::sqrt(mu / layer_rho[2 * i + g]));
            }
      }

      static double
      gauss_point(const double z0, const double z1, const unsigned int g)
      {
        const double c = 0.5 + (g == 0 ? -1. : 1.) * std::sqrt(3.) / 6.;
        return z0 + c * (z1 - z0);
      }

      /// The omega-independent part of A at zeta (non-dimensional).
      Matrix6
      static_matrix(const double zeta) const
      {
        const double nu   = plate.poisson(zeta * plate.h);
        const double E    = plate.E(zeta * plate.h) / E0;
        const double mu   = E / (2. * (1. + nu));
        const double Q11  = E / (1. - nu * nu);
        const double Q12  = nu * Q11;
        const double beta = nu / (1. - nu);
        const double C33  = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
        const double P = p * plate.h, Q = q * plate.h;
        Matrix6      A = Matrix6::Zero();
        A(0, 2)        = -P;
        A(0, 3)        = 1. / mu;
        A(1, 2)        = -Q;
        A(1, 4)        = 1. / mu;
        A(2, 0)        = beta * P;
        A(2, 1)        = beta * Q;
        A(2, 5)        = 1. / C33;
        A(3, 0)        = Q11 * P * P + mu * Q * Q;
        A(3, 1)        = (Q12 + mu) * P * Q;
        A(3, 5)        = -beta * P;
        A(4, 0)        = (Q12 + mu) * P * Q;
        A(4, 1)        = Q11 * Q * Q + mu * P * P;
        A(4, 5)        = -beta * Q;
        A(5, 3)        = P;
        A(5, 4)        = Q;
        return A;
      }

      /// Add the inertia term -rho omega^2 (non-dimensional) to A.
      void
      add_inertia(Matrix6 &A, const double rho, const double omega) const
      {
        const double r = rho * omega * omega * plate.h * plate.h / E0;
        A(3, 0) -= r;
        A(4, 1) -= r;
        A(5, 2) -= r;
      }

      /// Fourth-order Magnus step from the two Gauss-point matrices.
      static Matrix6
      magnus_step(const Matrix6 &A1, const Matrix6 &A2, const double d)
      {
        const Matrix6 Omega = 0.5 * d * (A1 + A2) +
                              (std::sqrt(3.) * d * d / 12.) * (A2 * A1 - A1 * A2);
        return expm(Omega);
      }

      /// Propagator of sub-layer i.
      Matrix6
      layer_propagator(const unsigned int i, const double omega) const
      {
        Matrix6 A1 = layer_A[2 * i], A2 = layer_A[2 * i + 1];
        add_inertia(A1, layer_rho[2 * i], omega);
        add_inertia(A2, layer_rho[2 * i + 1], omega);
        return magnus_step(A1, A2, nodes[i + 1] - nodes[i]);
      }

      /// Propagator from zeta0 to zeta1 (any sub-interval, evaluates the
      /// profiles afresh).
      Matrix6
      propagator(const double zeta0, const double zeta1, const double omega) const
      {
        Matrix6 A[2];
        for (unsigned int g = 0; g < 2; ++g)
          {
            const double zeta = gauss_point(zeta0, zeta1, g);
            A[g]              = static_matrix(zeta);
            add_inertia(A[g], plate.rho(zeta * plate.h), omega);
          }
        return magnus_step(A[0], A[1], zeta1 - zeta0);
      }

      /// Transfer matrix from zeta = 0 to zeta = 1.
      Matrix6
      transfer(const double omega) const
      {
        Matrix6 T = Matrix6::Identity();
        for (unsigned int i = 0; i + 1 < nodes.size(); ++i)
          T = layer_propagator(i, omega) * T;
        return T;
      }

      /// States at all sub-layer boundaries for the initial state y0.
      std::vector<Vector6>
      states(const Vector6 &y0, const double omega) const
      {
        std::vector<Vector6> y(nodes.size());
        y[0] = y0;
        for (unsigned int i = 0; i + 1 < nodes.size(); ++i)
          y[i + 1] = layer_propagator(i, omega) * y[i];
        return y;
      }

      Plate               plate;
      Options             options;
      double              p, q, k;
      double              E0;
      double              c_T_min;
      std::vector<double> nodes;
      std::vector<Matrix6> layer_A;
      std::vector<double> layer_rho;
    };
  } // namespace internal

  // ------------------------------------------------------------------------
  // Solutions through the thickness
  // ------------------------------------------------------------------------

  /// The amplitude functions of one separated solution (a static load case
  /// or a mode shape) at any z in [0, h]. Field = amplitude(z) times the
  /// in-plane factor given with each accessor; sin sin is evaluated by
  /// in_plane_factor().
  class ThicknessSolution
  {
  public:
    ThicknessSolution(std::shared_ptr<const internal::ThicknessProblem> problem,
                      const double                                      omega,
                      const Vector6                                    &y0)
      : problem(std::move(problem))
      , omega(omega)
      , y(this->problem->states(y0, omega))
    {}

    /// The physical state [U V W X Y Z](z) (SI units).
    Vector6
    state(const double z) const
    {
      const auto  &pr   = *problem;
      const double zeta = std::clamp(z / pr.plate.h, 0., 1.);
      // Sub-layer containing zeta.
      const auto it =
        std::upper_bound(pr.nodes.begin(), pr.nodes.end(), zeta);
      const std::size_t i = it - pr.nodes.begin() - 1; // nodes[0] = 0
      Vector6           s = y[i];
      if (zeta > pr.nodes[i]) // not at a node (then i + 1 < nodes.size())
        s = pr.propagator(pr.nodes[i], zeta, omega) * s;
      s.head<3>() *= pr.plate.h;
      s.tail<3>() *= pr.E0;
      return s;
    }

    /// u = U(z) cos(px) sin(qy).
    double U(const double z) const { return state(z)[0]; }
    /// v = V(z) sin(px) cos(qy).
    double V(const double z) const { return state(z)[1]; }
    /// w = W(z) sin(px) sin(qy), positive upward (+z).
    double W(const double z) const { return state(z)[2]; }
    /// sigma_xz = X(z) cos(px) sin(qy).
    double sigma_xz(const double z) const { return state(z)[3]; }
    /// sigma_yz = Y(z) sin(px) cos(qy).
    double sigma_yz(const double z) const { return state(z)[4]; }
    /// sigma_zz = Z(z) sin(px) sin(qy).
    double sigma_zz(const double z) const { return state(z)[5]; }
    /// sigma_xx = Sxx(z) sin(px) sin(qy).
    double sigma_xx(const double z) const { return in_plane_stresses(z)[0]; }
    /// sigma_yy = Syy(z) sin(px) sin(qy).
    double sigma_yy(const double z) const { return in_plane_stresses(z)[1]; }
    /// sigma_xy = Sxy(z) cos(px) cos(qy).
    double sigma_xy(const double z) const { return in_plane_stresses(z)[2]; }

    /// [Sxx, Syy, Sxy](z) from the state and the local material.
    Eigen::Vector3d
    in_plane_stresses(const double z) const
    {
      const auto  &pr   = *problem;
      const Vector6 s   = state(z);
      const double zc   = std::clamp(z, 0., pr.plate.h);
      const double nu   = pr.plate.poisson(zc);
      const double E    = pr.plate.E(zc);
      const double Q11  = E / (1. - nu * nu);
      const double Q12  = nu * Q11;
      const double mu   = E / (2. * (1. + nu));
      const double beta = nu / (1. - nu);
      return Eigen::Vector3d(-Q11 * pr.p * s[0] - Q12 * pr.q * s[1] + beta * s[5],
                             -Q12 * pr.p * s[0] - Q11 * pr.q * s[1] + beta * s[5],
                             mu * (pr.q * s[0] + pr.p * s[1]));
    }

    /// sin(px) sin(qy) at (x, y); e.g. at the plate centre
    /// sin(m pi / 2) sin(n pi / 2).
    double
    in_plane_factor(const double x, const double y) const
    {
      return std::sin(problem->p * x) * std::sin(problem->q * y);
    }

    /// The angular frequency (0 for statics).
    double angular_frequency() const { return omega; }

    /// Sub-layer boundaries z_i (SI units) and the states there, e.g. for
    /// thickness integrals.
    std::vector<double>
    nodes() const
    {
      std::vector<double> z(problem->nodes);
      for (double &zi : z)
        zi *= problem->plate.h;
      return z;
    }
    std::vector<Vector6>
    node_states() const
    {
      std::vector<Vector6> s(y);
      for (auto &si : s)
        {
          si.head<3>() *= problem->plate.h;
          si.tail<3>() *= problem->E0;
        }
      return s;
    }

  private:
    std::shared_ptr<const internal::ThicknessProblem> problem;
    double                                            omega;
    std::vector<Vector6>                              y; // non-dimensional
  };

  // ------------------------------------------------------------------------
  // 1. Static sinusoidal load
  // ------------------------------------------------------------------------

  /// Plate under the downward top-face pressure q0 sin(px) sin(qy),
  /// p = m pi / a, q = n pi / b, with traction-free bottom face. The centre
  /// deflection is -W(z) sin(m pi/2) sin(n pi/2) (positive downward).
  inline ThicknessSolution
  static_sinusoidal(const Plate       &plate,
                    const double       q0,
                    const unsigned int m       = 1,
                    const unsigned int n       = 1,
                    const Options     &options = Options())
  {
    auto pr = std::make_shared<const internal::ThicknessProblem>(plate,
                                                                 m,
                                                                 n,
                                                                 options);
    const Matrix6         T   = pr->transfer(0.);
    const Eigen::Matrix3d T21 = T.block<3, 3>(3, 0);
    const Eigen::Vector3d rhs(0., 0., -q0 / pr->E0);
    Vector6               y0 = Vector6::Zero();
    y0.head<3>()             = T21.fullPivLu().solve(rhs);
    return ThicknessSolution(pr, 0., y0);
  }

  /// Same with the profiles given separately (signature of the brief).
  inline ThicknessSolution
  static_sinusoidal(const Profile     &E,
                    const Profile     &rho,
                    const double       nu,
                    const double       a,
                    const double       b,
                    const double       h,
                    const double       q0,
                    const unsigned int m       = 1,
                    const unsigned int n       = 1,
                    const Options     &options = Options())
  {
    return static_sinusoidal(Plate{E, rho, nu, a, b, h}, q0, m, n, options);
  }

  // ------------------------------------------------------------------------
  // 2. Natural frequencies
  // ------------------------------------------------------------------------

  enum class ModeType
  {
    flexural,       ///< thickness mean of W dominates (bending)
    extensional,    ///< thickness mean of L = (pU + qV)/k dominates
    in_plane_shear, ///< W = L = 0: T = (qU - pV)/k only (SH mode)
    thickness       ///< none of these: higher-order thickness mode
  };

  inline const char *
  to_string(const ModeType t)
  {
    switch (t)
      {
        case ModeType::flexural:
          return "flexural";
        case ModeType::extensional:
          return "extensional";
        case ModeType::in_plane_shear:
          return "in-plane shear";
        default:
          return "thickness";
      }
  }

  /// One natural mode of (m, n).
  struct Mode
  {
    double       omega; ///< angular frequency [rad/s]
    unsigned int m, n;
    ModeType     type;
    /// Thickness means and mean squares of the mode shape, normalised by
    /// the total mean square of the displacement:
    /// mean_W^2 / msq, mean_L^2 / msq, and the mean-square fractions of
    /// W, L = (pU+qV)/k and T = (qU-pV)/k.
    double mean_W_fraction, mean_L_fraction;
    double W_fraction, L_fraction, T_fraction;
    /// Mode shape through the thickness (normalised, sign arbitrary).
    ThicknessSolution shape;

    double frequency_hz() const { return omega / (2. * M_PI); }
  };

  namespace internal
  {
    inline double
    boundary_determinant(const ThicknessProblem &pr, const double omega)
    {
      return pr.transfer(omega).block<3, 3>(3, 0).determinant();
    }

    inline Mode
    make_mode(const std::shared_ptr<const ThicknessProblem> &pr,
              const double                                   omega,
              const unsigned int                             m,
              const unsigned int                             n)
    {
      const Eigen::Matrix3d T21 = pr->transfer(omega).block<3, 3>(3, 0);
      Eigen::JacobiSVD<Eigen::Matrix3d> svd(T21, Eigen::ComputeFullV);
      Vector6 y0   = Vector6::Zero();
      y0.head<3>() = svd.matrixV().col(2);
      ThicknessSolution shape(pr, omega, y0);
      // Thickness integrals by the trapezoidal rule on the sub-layer nodes.
      const auto z = shape.nodes();
      const auto s = shape.node_states();
      double     mW = 0, mL = 0, eW = 0, eL = 0, eT = 0;
      for (std::size_t i = 0; i + 1 < z.size(); ++i)
        {
          const double dz = z[i + 1] - z[i];
          for (const std::size_t j : {i, i + 1})
            {
              const double W = s[j][2];
              const double L = (pr->p * s[j][0] + pr->q * s[j][1]) / pr->k;
              const double T = (pr->q * s[j][0] - pr->p * s[j][1]) / pr->k;
              mW += 0.5 * dz * W;
              mL += 0.5 * dz * L;
              eW += 0.5 * dz * W * W;
              eL += 0.5 * dz * L * L;
              eT += 0.5 * dz * T * T;
            }
        }
      const double h   = pr->plate.h;
      const double msq = (eW + eL + eT) / h;
      mW /= h;
      mL /= h;
      const double fW = mW * mW / msq, fL = mL * mL / msq;
      ModeType     type;
      if ((eW + eL) <= 1e-8 * (eW + eL + eT))
        type = ModeType::in_plane_shear;
      else if (fW > 0.5 && fW > fL)
        type = ModeType::flexural;
      else if (fL > 0.5)
        type = ModeType::extensional;
      else
        type = ModeType::thickness;
      const double tot = eW + eL + eT;
      return Mode{omega, m, n, type, fW, fL, eW / tot, eL / tot, eT / tot,
                  shape};
    }
  } // namespace internal

  /// The lowest natural angular frequencies of mode (m, n) with traction
  /// free faces, in increasing order: at most `count` of them (count = 0:
  /// no limit) and only those below omega_max (omega_max <= 0: no limit,
  /// the scan then stops after Options::scan_limit omega units). Each root
  /// is classified (ModeType) from its mode shape.
  inline std::vector<Mode>
  natural_frequencies(const Plate       &plate,
                      const unsigned int m,
                      const unsigned int n,
                      const unsigned int count,
                      const double       omega_max = 0.,
                      const Options     &options   = Options())
  {
    if (count == 0 && !(omega_max > 0.))
      throw std::invalid_argument("need a count or an omega_max");
    auto pr = std::make_shared<const internal::ThicknessProblem>(plate,
                                                                 m,
                                                                 n,
                                                                 options);
    const double unit =
      pr->c_T_min * std::min(pr->k, M_PI / plate.h);
    const double step = unit / options.scan_points;
    const double end =
      omega_max > 0. ? omega_max : options.scan_limit * unit;
    auto f = [&](const double omega) {
      return internal::boundary_determinant(*pr, omega);
    };
    std::vector<Mode> modes;
    double            w0 = 0., f0 = f(0.);
    if (f0 == 0.)
      throw std::runtime_error("singular static problem");
    while (w0 < end && (count == 0 || modes.size() < count))
      {
        const double w1 = std::min(w0 + step, end);
        const double f1 = f(w1);
        if ((f0 > 0.) != (f1 > 0.) || f1 == 0.)
          {
            const double root = internal::brent(f, w0, w1, f0, f1);
            modes.push_back(internal::make_mode(pr, root, m, n));
            if (f1 == 0.) // step off an exact zero
              {
                w0 = w1 * (1. + 1e-12);
                f0 = f(w0);
                continue;
              }
          }
        w0 = w1;
        f0 = f1;
      }
    if (omega_max <= 0. && count > 0 && modes.size() < count)
      throw std::runtime_error("natural_frequencies: fewer roots than asked "
                               "below Options::scan_limit");
    return modes;
  }

  /// Same with the profiles given separately (signature of the brief).
  inline std::vector<Mode>
  natural_frequencies(const Profile     &E,
                      const Profile     &rho,
                      const double       nu,
                      const double       a,
                      const double       b,
                      const double       h,
                      const unsigned int m,
                      const unsigned int n,
                      const unsigned int count,
                      const double       omega_max = 0.,
                      const Options     &options   = Options())
  {
    return natural_frequencies(Plate{E, rho, nu, a, b, h},
                               m,
                               n,
                               count,
                               omega_max,
                               options);
  }

} // namespace fgimpact_exact
