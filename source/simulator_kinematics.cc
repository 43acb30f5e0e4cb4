// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Simulator's part of Kinematics = auto (doc/theory.md, "Automatic
// kinematics"): promote blocks within a step, demote them after it, and
// set up what depends on the block models.

#include <ndda/scene/scene.h>
#include <ndda/simulator.h>

#include <algorithm>

namespace ndda
{
  template <int dim>
  void
  Simulator<dim>::setup_automatic_kinematics()
  {
    const auto strengths =
      ndda::parameters::material_strengths(parameters.materials);
    std::vector<std::optional<fracture::Strength>> cell_strength;
    for (const unsigned int m : fem.cell_material)
      cell_strength.push_back(strengths[m]);
    automatic.setup(mesh,
                    *fem.fe,
                    fem.dof_map,
                    fem.cell_auto,
                    cell_strength,
                    parameters.control.automatic_kinematics);
  }



  template <int dim>
  bool
  Simulator<dim>::promote_blocks(const Vector<double> *d)
  {
    if (!automatic.enabled() || parameters.fracture.criterion == nullptr)
      return false;
    const auto meshed = fem.meshed_blocks();
    if (!automatic.any_auto_block(meshed, false))
      return false;
    SectionTimer::Scope scope(timer, "kinematics switch");
    // The trial end of the step being solved: stresses advanced by d,
    // the contact forces the settled contacts will have. At the start:
    // the initial stresses.
    Vector<double> force;
    if (d != nullptr && parameters.contact.enabled)
      contacts.trial_end_forces(*d, force);
    const auto promote =
      automatic.promotions(mesh,
                           *parameters.fracture.criterion,
                           {d != nullptr ? stresses.trial_cell_means(*d) :
                                           stresses.cell_means(),
                            stresses.cell_areas(),
                            force,
                            parameters.materials.thickness},
                           meshed,
                           d != nullptr);
    if (promote.empty())
      return false;
    // An affine or rigid field is exact on the mesh: a promoted block
    // keeps its state.
    fem.set_block_models(promote, fem.model("meshed"));
    set_up_block_models(d == nullptr);
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::demote_blocks()
  {
    if (!automatic.enabled() || parameters.fracture.criterion == nullptr)
      return;
    const auto meshed = fem.meshed_blocks();
    if (!automatic.any_auto_block(meshed, true))
      return;
    SectionTimer::Scope  scope(timer, "kinematics switch");
    const Vector<double> no_force;
    const auto           demote =
      automatic.demotions(mesh,
                          *parameters.fracture.criterion,
                          {stresses.cell_means(),
                           stresses.cell_areas(),
                           parameters.contact.enabled ? contacts.end_forces() :
                                                        no_force,
                           parameters.materials.thickness},
                          meshed);
    if (demote.empty())
      return;
    fem.set_block_models(
      demote, fem.model(parameters.control.automatic_kinematics.start_model));
    set_up_block_models(false);
    // A demoted block's velocity and inertia force are fitted by its new
    // space (momentum and angular momentum kept).
    std::vector<bool> demoted(mesh.n_blocks(), false);
    for (const unsigned int b : demote)
      demoted[b] = true;
    fem.reduced_blocks.project(fem.linear_system.get_mass_matrix(),
                               kinematics.velocity,
                               &kinematics.inertia_force,
                               demoted);
    if (kinematics.acceleration.size() > 0)
      fem.reduced_blocks.project(fem.linear_system.get_mass_matrix(),
                                 kinematics.acceleration,
                                 nullptr,
                                 demoted);
  }



  template <int dim>
  void
  Simulator<dim>::set_up_block_models(const bool at_start)
  {
    fem.setup_system(parameters);
    block_lines_stale = false;
    if (parameters.contact.enabled)
      {
        contacts.set_reduced_blocks(fem.reduced_mesh_blocks());
      }
    fracture_check.setup(mesh,
                         fem.cell_material,
                         ndda::parameters::material_strengths(
                           parameters.materials),
                         fem.meshed_cells(),
                         parameters.fracture.nonlocal_radius);
    if (at_start)
      return;
    // The element matrices stay (they are the cells'); the system is
    // assembled on the new constraints.
    fem.update_matrices(parameters, true, displacement, stresses, true);
    ++n_matrix_rebuilds;
    compute_internal_force();
    fem.linear_system.invalidate();
  }



  template void
  Simulator<2>::setup_automatic_kinematics();
  template bool
  Simulator<2>::promote_blocks(const Vector<double> *);
  template void
  Simulator<2>::demote_blocks();
  template void
  Simulator<2>::set_up_block_models(const bool);
} // namespace ndda
