#ifndef fgimpact_impactor_profile_h
#define fgimpact_impactor_profile_h

#include <cmath>
#include <memory>
#include <string>

namespace fgimpact
{
  /**
   * The gap function of a resolved contact, as step-42's obstacle: the
   * height (m) of the impactor's surface above its lowest point at the
   * in-plane distance r (m) from it, measured vertically.  The resolved
   * contact's complementarity problem needs nothing else of the impactor's
   * shape, so another axisymmetric impactor (a flat punch with rounded
   * edges, a cone, a measured tip) is another implementation of this
   * class.
   */
  class ImpactorProfile
  {
  public:
    virtual ~ImpactorProfile() = default;

    /// The surface's height above its lowest point at r (m); r <= extent().
    virtual double
    height(const double r) const = 0;

    /// The largest r of the surface facing the plate (m): contact
    /// candidates lie within it.
    virtual double
    extent() const = 0;

    /// For the log ("spherical", "paraboloid").
    virtual std::string
    name() const = 0;
  };



  /// A sphere of radius R (m): R - sqrt(R^2 - r^2).
  class SphereProfile : public ImpactorProfile
  {
  public:
    explicit SphereProfile(const double R)
      : R(R)
    {}

    double
    height(const double r) const override
    {
      return R - std::sqrt(R * R - r * r);
    }
    double
    extent() const override
    {
      return R;
    }
    std::string
    name() const override
    {
      return "spherical";
    }

  private:
    const double R;
  };



  /// Hertz's approximation of a sphere of radius R (m): r^2 / (2 R).
  class ParaboloidProfile : public ImpactorProfile
  {
  public:
    explicit ParaboloidProfile(const double R)
      : R(R)
    {}

    double
    height(const double r) const override
    {
      return r * r / (2. * R);
    }
    double
    extent() const override
    {
      return R;
    }
    std::string
    name() const override
    {
      return "paraboloid";
    }

  private:
    const double R;
  };



  /// The factory: the sphere's exact profile or the paraboloid.
  inline std::shared_ptr<const ImpactorProfile>
  create_sphere_profile(const double R, const bool paraboloid)
  {
    if (paraboloid)
      return std::make_shared<ParaboloidProfile>(R);
    return std::make_shared<SphereProfile>(R);
  }
} // namespace fgimpact

#endif
