#include <deal.II/base/exceptions.h>

#include <fgimpact/base/files.h>
#include <fgimpact/output/contact_output.h>
#include <fgimpact/output/output_files.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// The polar angles of the sphere's rings from its lowest point (rad):
    /// the first 0.0005 (7.5 um from the axis for R = 15 mm), each step
    /// 1.2 times the last up to pi/48, then even up to the top pole
    /// (excluded).
    std::vector<double>
    sphere_ring_angles()
    {
      const double        even = numbers::PI / 48;
      std::vector<double> thetas;
      for (double step = 0.0005, theta = step; theta < numbers::PI - 0.5 * even;
           theta += step, step         = std::min(1.2 * step, even))
        thetas.push_back(theta);
      return thetas;
    }

    /// A sphere's surface: its points and triangles.
    struct SphereSurface
    {
      std::vector<Point<3>>                    points;
      std::vector<std::array<unsigned int, 3>> triangles;
    };

    /// The ball's surface with its lowest point at `lowest` (m), radius R.
    SphereSurface
    sphere_surface(const Point<3> &lowest, const double R)
    {
      // A latitude-longitude triangulation: rings of 48 points and the two
      // poles, at the reference position (touching the undeformed top face
      // at the impact point); the point field displacement_m moves it by w,
      // as WarpByVector moves the plate.  The rings are graded towards the
      // lowest point, where the ball touches the plate (sphere_ring_angles():
      // 70 rings): a contact of radius a = 0.01, 0.03, 0.05, 0.1 R spans 9,
      // 14, 17, 22 of them, so the ball does not look like a cone at the
      // contact's scale (24 even rings put the first at 7.5 degrees, 1.96 mm
      // from the axis for R = 15 mm, beyond the default scene's a = 0.8 mm).
      const std::vector<double> thetas   = sphere_ring_angles();
      const unsigned int        n_rings  = thetas.size() + 1;
      const unsigned int        n_around = 48;
      const Point<3>            centre(lowest[0], lowest[1], lowest[2] + R);
      std::vector<Point<3>>     points{centre + Point<3>(0, 0, -R)};
      for (unsigned int i = 1; i < n_rings; ++i)
        for (unsigned int j = 0; j < n_around; ++j)
          {
            const double theta = thetas[i - 1]; // from the bottom
            const double phi   = 2. * numbers::PI * j / n_around;
            points.push_back(centre +
                             Point<3>(R * std::sin(theta) * std::cos(phi),
                                      R * std::sin(theta) * std::sin(phi),
                                      -R * std::cos(theta)));
          }
      points.push_back(centre + Point<3>(0, 0, R));
      const unsigned int                       top = points.size() - 1;
      std::vector<std::array<unsigned int, 3>> triangles;
      const auto ring = [&](const unsigned int i, const unsigned int j) {
        return 1 + (i - 1) * n_around + j % n_around;
      };
      for (unsigned int j = 0; j < n_around; ++j)
        {
          triangles.push_back({{0, ring(1, j + 1), ring(1, j)}});
          triangles.push_back(
            {{top, ring(n_rings - 1, j), ring(n_rings - 1, j + 1)}});
          for (unsigned int i = 1; i + 1 < n_rings; ++i)
            {
              triangles.push_back(
                {{ring(i, j), ring(i, j + 1), ring(i + 1, j)}});
              triangles.push_back(
                {{ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)}});
            }
        }
      return {points, triangles};
    }
  } // namespace



  namespace
  {
    /// A PVD collection of (time in s, file name), written through a
    /// temporary name and a rename like the solution's PVD.
    void
    write_pvd(const std::string                                 &file,
              const std::vector<std::pair<double, std::string>> &entries)
    {
      std::ostringstream out;
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
             "version=\"0.1\">\n<Collection>\n";
      for (const auto &[t, name] : entries)
        out << "<DataSet timestep=\"" << t << "\" file=\"" << name << "\"/>\n";
      out << "</Collection>\n</VTKFile>\n";
      write_file_atomically(file, out.str());
    }

    /// The header of an ASCII unstructured grid with the given points.
    void
    begin_grid(std::ostream                &out,
               const std::vector<Point<3>> &points,
               const unsigned int           n_cells)
    {
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
             "version=\"0.1\">\n<UnstructuredGrid>\n";
      out << "<Piece NumberOfPoints=\"" << points.size()
          << "\" NumberOfCells=\"" << n_cells << "\">\n<Points>\n"
          << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n";
      for (const auto &p : points)
        out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      out << "</DataArray>\n</Points>\n";
    }
  } // namespace



  ContactVtuWriter::ContactVtuWriter(const std::string   &directory,
                                     const Point<3>      &impact_point,
                                     const double         radius,
                                     const ContactModel  &contact,
                                     const PlateGeometry *mirror)
    : directory(directory)
    , impact_point(impact_point)
    , R(radius)
    , contact(contact)
    , mirror(mirror)
  {}



  void
  ContactVtuWriter::write(const std::string         &tag,
                          const double               t,
                          const double               w,
                          const ContactState        &state,
                          const std::vector<double> &node_uz)
  {
    // The pieces in vtu/ (created by the plate's writer, or here when
    // the two run apart), the PVD files at the top.
    std::error_code error;
    std::filesystem::create_directories(directory + "/vtu", error);
    const std::string sphere = "vtu/sphere_" + tag + ".vtu";
    write_sphere(directory + "/" + sphere, w, state.force);
    add_pvd_entry(spheres, {t, sphere});
    if (!contact.contact_points().empty())
      {
        const std::string nodes = "vtu/contact_" + tag + ".vtu";
        write_nodes(directory + "/" + nodes, state, node_uz);
        add_pvd_entry(contacts, {t, nodes});
      }
  }



  void
  ContactVtuWriter::write_sphere(const std::string &file,
                                 const double       w,
                                 const double       F) const
  {
    const auto [points, triangles] =
      sphere_surface(impact_point, R); // at the reference position

    std::ostringstream out;
    out.precision(10);
    begin_grid(out, points, triangles.size());
    out << "<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" "
           "format=\"ascii\">\n";
    for (const auto &t : triangles)
      out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 1; k <= triangles.size(); ++k)
      out << 3 * k << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 0; k < triangles.size(); ++k)
      out << "5\n";
    out << "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement_m\">\n"
        << "<DataArray type=\"Float64\" Name=\"displacement_m\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (unsigned int k = 0; k < points.size(); ++k)
      out << "0 0 " << -w << '\n';
    out << "</DataArray>\n</PointData>\n<CellData>\n"
        << "<DataArray type=\"Float64\" Name=\"contact_force_N\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 0; k < triangles.size(); ++k)
      out << F << '\n';
    out << "</DataArray>\n<DataArray type=\"Float64\" "
           "Name=\"impactor_displacement_um\" format=\"ascii\">\n";
    for (unsigned int k = 0; k < triangles.size(); ++k)
      out << w * 1e6 << '\n';
    out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n"
           "</VTKFile>\n";
    write_file_atomically(file, out.str());
  }



  ContactVtuWriter::Nodes
  ContactVtuWriter::nodes_to_write() const
  {
    // Read each time: the candidate set may have grown.
    Nodes nodes;
    nodes.points = contact.contact_points();
    nodes.source.resize(nodes.points.size());
    std::iota(nodes.source.begin(), nodes.source.end(), 0u);
    nodes.factor.assign(nodes.points.size(), 1.);
    if (mirror == nullptr)
      return nodes;
    const double centre[2] = {0.5 * mirror->length(), 0.5 * mirror->width()};
    for (unsigned int d = 0; d < 2; ++d)
      if (mirror->is_cut(d))
        {
          // On the cut plane to a millionth of the plate's size.
          const double      tol = 1e-6 * (mirror->length() + mirror->width());
          const std::size_t n   = nodes.points.size();
          for (std::size_t k = 0; k < n; ++k)
            if (std::abs(nodes.points[k][d] - centre[d]) <= tol)
              nodes.factor[k] *= 2.; // itself and its image: one node
            else
              {
                Point<3> image = nodes.points[k];
                image[d]       = 2. * centre[d] - image[d];
                nodes.points.push_back(image);
                nodes.source.push_back(nodes.source[k]);
                nodes.factor.push_back(nodes.factor[k]);
              }
        }
    return nodes;
  }



  void
  ContactVtuWriter::write_nodes(const std::string         &file,
                                const ContactState        &state,
                                const std::vector<double> &node_uz) const
  {
    const Nodes               nodes = nodes_to_write();
    const std::vector<double> areas = contact.contact_areas();
    const std::size_t         n     = nodes.points.size();
    std::ostringstream        out;
    out.precision(10);
    begin_grid(out, nodes.points, n);
    out << "<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 0; k < n; ++k)
      out << k << '\n';
    out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 1; k <= n; ++k)
      out << k << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 0; k < n; ++k)
      out << "1\n";
    out << "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement_m\">\n"
        << "<DataArray type=\"Float64\" Name=\"contact_pressure_MPa\" "
           "format=\"ascii\">\n";
    // (No forces yet at t = 0.)
    const auto force = [&](const unsigned int k) {
      const unsigned int s = nodes.source[k];
      return s < state.forces.size() ? state.forces[s] : 0.;
    };
    for (unsigned int k = 0; k < n; ++k)
      out << force(k) / areas[nodes.source[k]] * 1e-6 << '\n';
    out << "</DataArray>\n<DataArray type=\"Float64\" "
           "Name=\"nodal_force_N\" format=\"ascii\">\n";
    for (unsigned int k = 0; k < n; ++k)
      out << nodes.factor[k] * force(k) << '\n';
    // The nodes' z displacement (their in-plane displacement is not
    // known here: it is in the plate's field).
    out << "</DataArray>\n<DataArray type=\"Float64\" "
           "Name=\"displacement_m\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int s = nodes.source[k];
        out << "0 0 " << (s < node_uz.size() ? node_uz[s] : 0.) << '\n';
      }
    out << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n"
           "</VTKFile>\n";
    write_file_atomically(file, out.str());
  }



  void
  ContactVtuWriter::finish() const
  {
    write_pvd(directory + "/sphere.pvd", spheres);
    if (!contacts.empty())
      write_pvd(directory + "/contact.pvd", contacts);
  }



  void
  ContactVtuWriter::restore(const std::vector<Record> &sphere_records,
                            const std::vector<Record> &contact_records)
  {
    spheres  = sphere_records;
    contacts = contact_records;
    if (!spheres.empty())
      finish();
  }
} // namespace fgimpact
