// Output/Probe points: the entry, its syntax and its checks (ProbePoints);
// the weights and the evaluation are in probe_set.cc.

#include <deal.II/base/utilities.h>

#include <fgimpact/plate/probe_set.h>

#include <cctype>
#include <set>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    const std::string entry = "Output/Probe points";

    [[noreturn]] void
    refuse(const std::string &text)
    {
      AssertThrow(false, ExcMessage(entry + ": " + text));
      std::abort(); // not reached
    }

    std::string
    trim(const std::string &s)
    {
      const auto begin = s.find_first_not_of(" \t");
      const auto end   = s.find_last_not_of(" \t");
      return begin == std::string::npos ? "" : s.substr(begin, end - begin + 1);
    }

    /// A coordinate: a number in m, or a number followed by the letter of
    /// its plate dimension (fraction of a, b or h).
    std::pair<double, bool>
    parse_coordinate(const std::string &text,
                     const char         letter,
                     const std::string &point)
    {
      const std::string t        = trim(text);
      const bool        fraction = !t.empty() && t.back() == letter;
      const std::string number = fraction ? trim(t.substr(0, t.size() - 1)) : t;
      std::size_t       used   = 0;
      double            value  = 0;
      try
        {
          value = std::stod(number, &used);
        }
      catch (...)
        {
          used = 0;
        }
      if (number.empty() || used != number.size() || !std::isfinite(value))
        refuse("'" + point + "': the coordinate '" + t +
               "' is not a number in m or a fraction followed by '" +
               std::string(1, letter) + "'.");
      return {value, fraction};
    }
  } // namespace



  Point<3>
  ProbePoint::location(const double a, const double b, const double h) const
  {
    const double size[3] = {a, b, h};
    Point<3>     p;
    for (unsigned int d = 0; d < 3; ++d)
      p[d] = fraction[d] ? value[d] * size[d] : value[d];
    return p;
  }



  void
  ProbePoints::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Probe points",
      default_points,
      Patterns::Anything(),
      "Points whose displacement, velocity, acceleration and recovered "
      "stress an impact run writes to probes.csv at every time step (with "
      "the total support reaction): 'name: x, y, z' separated by ';'. "
      "Coordinates in m (as every length of the input) from the corner "
      "(0, 0, 0) (z from the bottom face), or as a fraction of the plate's length, width or thickness "
      "with the suffix a, b or h (0.5a = the middle of the length). Names: "
      "letters, digits and '_'. Empty: no probes.csv. The default: the "
      "centre of the mid-plane, the top and the bottom face.");
  }



  void
  ProbePoints::parse_parameters(ParameterHandler &prm)
  {
    points = parse(prm.get("Probe points"));
  }



  std::vector<ProbePoint>
  ProbePoints::parse(const std::string &text)
  {
    std::vector<ProbePoint> list;
    std::set<std::string>   names;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        if (trim(item).empty())
          continue;
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          refuse("'" + trim(item) + "' is not of the form 'name: x, y, z'.");
        ProbePoint point;
        point.name = trim(item.substr(0, colon));
        if (point.name.empty() ||
            point.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz"
                                         "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_") != std::string::npos)
          refuse("the name '" + point.name +
                 "' may only hold letters, digits and '_'.");
        if (!names.insert(point.name).second)
          refuse("the name '" + point.name + "' appears twice.");
        const auto coordinates =
          Utilities::split_string_list(item.substr(colon + 1), ',');
        if (coordinates.size() != 3)
          refuse("'" + point.name + "' needs three coordinates x, y, z.");
        for (unsigned int d = 0; d < 3; ++d)
          std::tie(point.value[d], point.fraction[d]) =
            parse_coordinate(coordinates[d], "abh"[d], point.name);
        list.push_back(point);
      }
    return list;
  }



  void
  ProbePoints::validate(const double a, const double b, const double h) const
  {
    const double size[3] = {a, b, h};
    for (const auto &point : points)
      {
        const Point<3> p = point.location(a, b, h);
        for (unsigned int d = 0; d < 3; ++d)
          if (p[d] < -1e-12 * size[d] || p[d] > size[d] * (1. + 1e-12))
            {
              std::ostringstream text;
              text << "'" << point.name << "' at (" << p[0] * 1e3 << ", "
                   << p[1] * 1e3 << ", " << p[2] * 1e3
                   << ") mm lies outside the plate (0.." << a * 1e3 << ", 0.."
                   << b * 1e3 << ", 0.." << h * 1e3 << " mm).";
              refuse(text.str());
            }
      }
  }
} // namespace fgimpact
