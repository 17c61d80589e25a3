// PlateModel::Parameters: the subsection Finite element (plate_model.h).

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/plate/plate_model.h>

namespace fgimpact
{
  namespace
  {
    /// Finite element/Volumetric strain: true for the cell's mean.
    const SelectionTable<bool> volumetric_strain_names = {{"pointwise", false},
                                                          {"cell mean", true}};
  } // namespace



  namespace
  {
    /// The entries of PlateModel::Parameters that set a member as they stand.
    const ParameterTable<PlateModel::Parameters> &
    finite_element_table()
    {
      using P                              = PlateModel::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Degree",
              &P::degree,
              Patterns::Integer(1, 2),
              "Polynomial degree p of the FE_Q(p)^3 displacement "
              "element: 1 = the paper's 8-node graded brick, 2 = "
              "27-node brick.");
        t.add(
          "Volumetric strain",
          &P::mean_dilatation,
          volumetric_strain_names,
          "The element's volumetric strain div u, in the stiffness and in every "
          "strain and stress written: pointwise (the paper's fully integrated "
          "brick), or the cell's mean (B-bar: Simo and Hughes' mean "
          "dilatation, Abaqus' C3D8 with selectively reduced integration), "
          "which does not lock when the material is nearly incompressible "
          "(Poisson's ratio near 1/2, or J2 plastic flow: a pressure that "
          "jumps sign between nodes). With Degree = 2 one constant per cell "
          "is a poor pressure (Q2-P0): use it with Degree = 1.");
        t.add(
          "Incompatible modes",
          &P::incompatible_modes,
          Patterns::Bool(),
          "With Degree = 1: add Wilson and Taylor's incompatible modes (Abaqus' "
          "C3D8I), nine internal bubbles per brick condensed out of its "
          "stiffness, so that a brick bends without the parasitic shear that "
          "makes the 8-node brick too stiff in bending (the base mesh's "
          "largest error in the plate's deflection). Every strain and stress "
          "written includes them. Elastic plates only.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  PlateModel::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    {
      finite_element_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  PlateModel::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    finite_element_table().parse(prm, *this);
    prm.leave_subsection();
  }
} // namespace fgimpact
