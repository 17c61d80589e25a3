#ifndef fgimpact_contact_output_h
#define fgimpact_contact_output_h

#include <deal.II/base/point.h>

#include <fgimpact/contact/contact_model.h>
#include <fgimpact/plate/geometry.h>

#include <string>
#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The ball and the contact for ParaView, beside the plate's VTU series:
   * at every VTU step a triangulated sphere surface (sphere_NNNNN.vtu, with
   * the contact force and the ball's displacement as cell data) and, for a
   * contact model with several contact nodes, those nodes as points with
   * their force and nodal pressure (contact_NNNNN.vtu).  Both are written
   * at their reference positions (the ball touching the undeformed top
   * face at the impact point, the nodes undeformed), in Directory/vtu/,
   * with the point field
   * displacement_m, as the plate's solution: one WarpByVector with the
   * same scale factor on plate, ball and nodes shows them where they are
   * (factor 1) or magnified alike.  Each series has its PVD file (sphere.pvd,
   * contact.pvd, at the top) with the simulation time in µs.  Everything is
   * replicated on the MPI ranks: rank 0 alone writes.  Every file is written to
   * a temporary name and renamed.
   */
  class ContactVtuWriter
  {
  public:
    /// impact_point: where the ball first touches the top face (m);
    /// mirror: a symmetric part's geometry, whose contact nodes are then
    /// written with their reflections across the cut planes (nullptr:
    /// the modelled nodes only).
    ContactVtuWriter(const std::string   &directory,
                     const Point<3>      &impact_point,
                     const double         radius,
                     const ContactModel  &contact,
                     const PlateGeometry *mirror = nullptr);

    /// Write the snapshot `tag` (the step's 5 digits, or an extra
    /// snapshot's name; one of the same tag is replaced in the PVD) at
    /// time t (µs), with the ball's
    /// displacement w (m, positive down) and the z displacement of the
    /// plate at each contact node (m, positive up; in the order of
    /// ContactModel::contact_points(); empty: zero).
    void
    write(const std::string         &tag,
          const double               t,
          const double               w,
          const ContactState        &state,
          const std::vector<double> &node_uz = {});

    /// Write the PVD files (through a temporary name and a rename).
    void
    finish() const;

    /// (time in µs, file name in the output directory) of a PVD entry.
    using Record = std::pair<double, std::string>;

    /// The PVD entries so far (for a checkpoint).
    const std::vector<Record> &
    sphere_records() const
    {
      return spheres;
    }
    const std::vector<Record> &
    contact_records() const
    {
      return contacts;
    }

    /// On resume: the checkpoint's entries; the PVD files are rewritten
    /// with them (dropping snapshots written after the checkpoint).
    void
    restore(const std::vector<Record> &sphere_records,
            const std::vector<Record> &contact_records);

  private:
    void
    write_sphere(const std::string &file, const double w, const double F) const;
    void
    write_nodes(const std::string         &file,
                const ContactState        &state,
                const std::vector<double> &node_uz) const;

    /// The nodes to write: the model's, and with `mirror` their
    /// reflections (a node on a cut plane once, with its force doubled as
    /// on the whole plate; the area likewise, so the pressure is the
    /// part's), with each one's source node and force factor.
    struct Nodes
    {
      std::vector<Point<3>>     points;
      std::vector<unsigned int> source;
      std::vector<double>       factor;
    };
    Nodes
    nodes_to_write() const;

    const std::string                           directory;
    const Point<3>                              impact_point;
    const double                                R;
    const ContactModel                         &contact;
    const PlateGeometry                        *mirror;
    std::vector<std::pair<double, std::string>> spheres, contacts;
  };
} // namespace fgimpact

#endif
