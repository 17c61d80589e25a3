#ifndef fgimpact_geometry_h
#define fgimpact_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// Support condition of one side face of the plate.
  enum class SideSupport
  {
    /// Eq. 2.15 on the whole face: w = 0 and the tangential in-plane
    /// displacement = 0 (v on x = const faces, u on y = const faces).
    simply_supported,
    /// u = v = w = 0 on the whole face.
    clamped,
    /// Traction free.
    free
  };

  /// Geometry/Symmetry: how much of the plate is modelled.
  enum class Symmetry
  {
    /// The smallest part the scene allows (quarter, half or none).
    automatic,
    /// The whole plate.
    none,
    /// One half: cut at x = a/2 if the scene allows it, else y = b/2.
    half,
    /// One quarter: cuts at x = a/2 and y = b/2.
    quarter
  };

  /// Where and how much to refine the mesh under the impact point.
  struct LocalRefinement
  {
    /// The impact point on the top face (m).
    Point<3> centre;
    /// Radius (m) of the core that gets the finest cells.
    double radius = 0;
    /// Number of refinement levels (0: none).
    unsigned int levels = 0;
    /// The contact radius the scene expects (m; 0: none), which sizes a
    /// resolved contact's candidate set (estimate_resources()).
    double contact_radius = 0;
  };

  /// One more refinement of an adaptive run's final mesh, for its error
  /// estimate (Geometry/Adaptive refinement estimate): every cell is split
  /// by exactly one of contact_zone and rest_of_plate.
  enum class MeshSplit
  {
    /// None: the mesh as the refinements made it.
    none,
    /// The cells one more contact refinement level would split (the finest
    /// cells within the core radius plus two of their edges).
    contact_zone,
    /// Every other cell: the plate's mesh in plane and through the
    /// thickness, away from the contact.
    rest_of_plate
  };

  /// The share of the whole plate that a part cut at x = a/2 (cut[0])
  /// and y = b/2 (cut[1]) models: 1, 1/2 or 1/4.
  inline double
  part_share(const std::array<bool, 2> &cut)
  {
    return (cut[0] ? 0.5 : 1.) * (cut[1] ? 0.5 : 1.);
  }

  /// Its name, as Geometry/Symmetry spells it: none, half or quarter.
  inline std::string
  part_name(const std::array<bool, 2> &cut)
  {
    return cut[0] && cut[1] ? "quarter" : cut[0] || cut[1] ? "half" : "none";
  }



  /**
   * The plate a x b x h, x and y in-plane, z through the thickness from the
   * bottom face, meshed by GridGenerator::subdivided_hyper_rectangle with
   * colorized boundary ids:
   *   0: x = 0,  1: x = a,  2: y = 0,  3: y = b,  4: z = 0 (bottom),
   *   5: z = h (top, impacted).
   */
  class PlateGeometry
  {
  public:
    struct Parameters
    {
      double       length         = 0.2;  // a, m
      double       width          = 0.1;  // b, m
      double       thickness      = 0.02; // h, m
      unsigned int subdivisions_x = 40;
      unsigned int subdivisions_y = 20;
      unsigned int subdivisions_z = 4;
      /// Supports of the faces x = 0, x = a, y = 0, y = b (ids 0-3).
      std::array<SideSupport, 4> supports = {{SideSupport::simply_supported,
                                              SideSupport::simply_supported,
                                              SideSupport::simply_supported,
                                              SideSupport::simply_supported}};
      /// Support of the bottom face z = 0 (id 4): simply supported is
      /// w = 0 only (a frictionless rigid base).
      SideSupport bottom_support = SideSupport::free;
      /// Boundary conditions/In-plane edges = immovable: a simply
      /// supported side also holds the in-plane displacement normal to it
      /// on the mid-plane z = h/2 (the edge may still rotate).
      bool immovable_edges = false;
      /// Contact refinement: levels as given (auto: chosen from the scene
      /// by Simulator::contact_refinement(), levels then 0 here) and the
      /// core radius (m, 0: automatic).
      bool         contact_refinement_auto   = true;
      unsigned int contact_refinement_levels = 0;
      double       contact_refinement_radius = 0;
      /// Geometry/Adaptive refinement cycles: pilot runs whose time
      /// integrated error indicator refines the mesh for the next run
      /// (0: none); the fraction of the cells each cycle refines.
      unsigned int adaptive_cycles   = 0;
      double       adaptive_fraction = 0.2;
      /// Geometry/Adaptive refinement estimate: three more runs (the final
      /// mesh's contact zone split, the rest of it split, half the time
      /// step) bound the final run's error, one source each.
      bool adaptive_estimate = false;
      /// Geometry/Symmetry as requested (resolve_symmetry(), symmetry.cc,
      /// decides the planes to cut once the whole scene is known).
      Symmetry symmetry = Symmetry::automatic;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /// The plate, or with cut[d] the part x <= a/2 (d = 0), y <= b/2
    /// (d = 1) of it (resolve_symmetry() decides).
    explicit PlateGeometry(const Parameters          &parameters,
                           const std::array<bool, 2> &cut = {{false, false}});

    /**
     * Fill an empty triangulation with the subdivided brick.  The same
     * cells are made as the coarsest brick whose subdivisions are the
     * requested ones divided by 2^k (k as large as all three allow),
     * refined k times: p4est keeps the coarse mesh on every MPI rank, so
     * a coarse mesh of 2^{3k} times fewer cells is what lets large meshes
     * run on many ranks.
     */
    void
    create_triangulation(Triangulation<3> &triangulation) const;

    /**
     * Refine the cells near refinement.centre refinement.levels times:
     * in pass l every cell of the finest level so far whose distance from
     * the centre is below radius + 2 h_cell (h_cell its edge along x) is
     * split, so the zones are nested and each level's zone extends two of
     * its cells beyond the next; p4est keeps the mesh 2:1 balanced and the
     * hanging nodes are constrained by the plate model.
     */
    static void
    refine_locally(Triangulation<3>      &triangulation,
                   const LocalRefinement &refinement);

    /**
     * Refine the active cells whose CellId strings are in each list, one
     * list after the other (the cycles of an adaptive run: each list names
     * cells of the mesh the lists before it made).  p4est keeps the mesh
     * 2:1 balanced, which may refine a neighbour too; that is the same on
     * every rebuild, so the lists remake the same mesh.
     */
    static void
    refine_cells(Triangulation<3>                            &triangulation,
                 const std::vector<std::vector<std::string>> &cycles);

    /**
     * Split the cells of `split` once (nothing for MeshSplit::none): the
     * contact zone is what one more pass of refine_locally() with
     * refinement's centre and radius splits, the rest of the plate every
     * other active cell.
     */
    static void
    split_cells(Triangulation<3>      &triangulation,
                const LocalRefinement &refinement,
                const MeshSplit        split);

    double
    length() const
    {
      return parameters.length;
    }
    double
    width() const
    {
      return parameters.width;
    }
    double
    thickness() const
    {
      return parameters.thickness;
    }

    /// Whether the model is cut at the symmetry plane x = a/2 (d = 0) or
    /// y = b/2 (d = 1): the part modelled is then x <= a/2 (y <= b/2), and
    /// the cut face (boundary id 1 or 3) carries u_x = 0 (u_y = 0).
    bool
    is_cut(const unsigned int d) const
    {
      return cut[d];
    }

    /// The modelled part's share of the whole plate: 1, 1/2 or 1/4.  Sums
    /// over the part (forces, masses, energies) times 1/share() are the
    /// whole plate's.
    double
    share() const
    {
      return part_share(cut);
    }

    /// none, half or quarter (part_name()).
    std::string
    part_name() const
    {
      return fgimpact::part_name(cut);
    }

    /// How many points of the whole plate the part's point p stands for:
    /// 1 on every cut plane it lies on, 2 for every cut it lies off.
    unsigned int
    multiplicity(const Point<3> &p) const;

    /// Centre of the plate at height z (m).
    Point<3>
    centre(const double z) const;

    /// Whether p lies inside the closed plate up to a relative tolerance.
    bool
    contains(const Point<3> &p) const;

    const Parameters &
    get_parameters() const
    {
      return parameters;
    }

    /// The names of the four side faces, in the order of `supports`.
    static const std::array<std::string, 4> side_names;

  private:
    const Parameters          parameters;
    const std::array<bool, 2> cut;
  };
} // namespace fgimpact

#endif
