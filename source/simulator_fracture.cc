// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Simulator's part of fracture (thesis chapter 5, doc/fracture.md):
// check the edges, advance crack tips along the stress, crack edges and
// carry the state to the cracked mesh.

#include <ndda/mesh/refinement.h>
#include <ndda/mesh/state_transfer.h>
#include <ndda/scene/scene.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <limits>
#include <optional>

namespace ndda
{
  namespace
  {
    /**
     * Fracture/Tip mesh size: after a crack, bisect the cells near every
     * crack tip until their longest edge is at most h + (g - 1) d, d the
     * distance from the cell's centroid to the nearest tip of its block
     * (tips of the cracked mesh). No refinement if the entry is 0.
     */
    RefineAfterCrack
    refinement_near_tips(const parameters::Parameters &prm,
                         const unsigned int            n_cells)
    {
      RefineAfterCrack refine;
      const double     h = prm.fracture.tip_mesh_size;
      if (!(h > 0.))
        return refine;
      const double slope = prm.geometry.grading.growth_rate - 1.;
      refine.size_bound  = [h, slope](const geometry::BlockMesh   &mesh,
                                     const std::vector<Point<2>> &initial) {
        std::vector<unsigned int> vertex_block(mesh.vertices.size());
        for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
          for (const unsigned int v : mesh.triangles[c])
            vertex_block[v] = mesh.cell_block[c];
        std::vector<std::vector<Point<2>>> tips(mesh.block_names.size());
        for (const auto &tip : fracture::find_crack_tips(mesh, initial))
          tips[vertex_block[tip.vertex]].push_back(mesh.vertices[tip.vertex]);
        return RefineAfterCrack::SizeBound(
          [h, slope, tips](const unsigned int block, const Point<2> &x) {
            double size = std::numeric_limits<double>::infinity();
            for (const auto &tip : tips[block])
              size = std::min(size, h + slope * x.distance(tip));
            return size;
          });
      };
      refine.max_cells = prm.geometry.max_cells;
      refine.what      = "Fracture/Tip mesh size = " + std::to_string(h) +
                    " m, refining " + std::to_string(n_cells) +
                    " cells around the crack tips (Geometry/Maximum number "
                    "of cells = " +
                    std::to_string(refine.max_cells) + ")";
      return refine;
    }
  } // namespace



  template <int dim>
  std::vector<std::array<unsigned int, 2>>
  Simulator<dim>::check_fracture(const Vector<double> &d, const double dt)
  {
    SectionTimer::Scope scope(timer, "fracture check");
    const auto         &block_mesh = mesh.get_block_mesh();
    // The step's trial end: vertices moved by the increment, stresses
    // advanced by it (as commit_step() will do, if no edge cracks).
    std::vector<Point<dim>> end_vertices = block_mesh.vertices;
    const auto              increment    = fem.dof_map.vertex_values(d);
    for (unsigned int v = 0; v < end_vertices.size(); ++v)
      end_vertices[v] += increment[v];
    return fracture_check.check(parameters.fracture,
                                block_mesh.triangles,
                                stresses.cell_areas(),
                                {block_mesh.vertices, stresses.cell_means()},
                                {end_vertices, stresses.trial_cell_means(d)},
                                time,
                                dt);
  }



  template <int dim>
  void
  Simulator<dim>::crack_edges(
    const std::vector<std::array<unsigned int, 2>> &edges)
  {
    SectionTimer::Scope scope(timer, "crack");
    // What the old dof numbering carries, before crack() empties the
    // DoFHandler: dof vectors by cell, the acceleration as M a over the
    // lumped mass.
    const std::vector<types::global_dof_index> old_cell_dofs =
      fem.dof_map.cell_dofs;
    const Vector<double> acceleration =
      fem.linear_system.lumped_acceleration(kinematics.inertia_force);
    const Vector<double>          old_displacement(displacement);
    const Vector<double>          old_velocity(kinematics.velocity);
    const Vector<double>          old_acceleration(kinematics.acceleration);
    const std::vector<double>     bolt_forces = fem.bolts.axial_forces();
    const contact::ContactHandler old_contacts(contacts);

    // Fracture/Tip mesh size: the cells near the tips are bisected in the
    // same rebuild; the per-cell state goes to the parts, the dof vectors
    // below too.
    const CrackResult cracked =
      mesh.crack(edges,
                 refinement_near_tips(parameters,
                                      mesh.get_block_mesh().triangles.size()));
    n_cracked_edges += edges.size();
    for (const auto &edge : cracked.cracked_edges)
      automatic.mark_cracked({edge.cells[0], edge.cells[1]});
    const std::optional<refinement::RefineResult> &refined = cracked.refined;
    if (refined)
      {
        const auto &origin = refined->cell_origin;
        std::vector<std::vector<StressField::Stress>> cell_stresses =
          stresses.by_cell();
        state_transfer::transfer_refined(
          make_element(parameters.control.finite_element).cell_quadrature,
          fem.fe->degree - 1,
          *refined,
          cell_stresses);
        stresses.set_by_cell(cell_stresses);
        fem.frames.carry_to_cells(origin);
        fem.element_cache.carry_to_cells(*refined);
        std::vector<const kinematics::BlockKinematics *> model;
        std::vector<bool>                                is_auto;
        for (const unsigned int c : origin)
          {
            model.push_back(fem.cell_model[c]);
            is_auto.push_back(fem.cell_auto[c]);
          }
        fem.cell_model.swap(model);
        fem.cell_auto.swap(is_auto);
      }

    setup_dofs(false);
    const auto transfer = [&](const Vector<double> &old, Vector<double> &now) {
      now.reinit(fem.dof_handler.n_dofs());
      if (refined)
        state_transfer::transfer_refined(*fem.fe,
                                         old_cell_dofs,
                                         *refined,
                                         fem.dof_map.cell_dofs,
                                         {&old},
                                         {&now});
      else
        state_transfer::transfer_dof_values(old_cell_dofs,
                                            old,
                                            fem.dof_map.cell_dofs,
                                            now);
    };
    transfer(old_displacement, displacement);
    transfer(old_velocity, kinematics.velocity);
    if (old_acceleration.size() > 0)
      transfer(old_acceleration, kinematics.acceleration);
    Vector<double> new_acceleration;
    transfer(acceleration, new_acceleration);
    // Constraints, bolts, loads and measure points are found by position
    // on the scene's initial geometry.
    mesh.on_initial_geometry([&]() {
      fem.setup_constraints(parameters);
      fem.bolts.set_axial_forces(bolt_forces);
      fem.setup_loads(parameters);
      measure_points.setup(
        mesh, *fem.fe, fem.dof_map, parameters.output.measure_points, true);
    });
    fem.setup_system(parameters);
    setup_contacts();
    if (parameters.contact.enabled)
      contacts.carry_memory_from(old_contacts);
    fracture_check.setup(mesh,
                         fem.cell_material,
                         ndda::parameters::material_strengths(
                           parameters.materials),
                         fem.meshed_cells(),
                         parameters.fracture.nonlocal_radius);

    // A crack changes no cell's shape (cells keep their index, vertex
    // order and geometry; only dof numbers change): element matrices are
    // recomputed only for cells that moved beyond the tolerance since
    // their last computation, as in any step. Then global matrices,
    // gravity, internal force, loaded faces, and M a on the new mesh.
    setup_automatic_kinematics();
    fem.update_matrices(parameters, true, displacement, stresses, true);
    ++n_matrix_rebuilds;
    compute_internal_force();
    kinematics.inertia_force =
      fem.linear_system.lumped_inertia_force(new_acceleration);
    external_force.reinit(fem.dof_handler.n_dofs());
    assemble_external_force(time, external_force);
    fem.linear_system.invalidate();
  }



  template <int dim>
  std::vector<std::array<unsigned int, 2>>
  Simulator<dim>::advance_crack_tips(
    const std::vector<std::array<unsigned int, 2>> &failing,
    const Vector<double>                           &d)
  {
    SectionTimer::Scope scope(timer, "crack tip advance");
    // Vertices that must stay: constrained nodes and bolt anchors (both
    // are found by position on the initial geometry after the crack).
    std::vector<bool> fixed(mesh.get_block_mesh().vertices.size(), false);
    const auto       &affine = fem.constraints.affine_constraints();
    std::vector<types::global_dof_index> anchors = fem.bolts.anchor_dofs();
    for (const auto &node : fem.constraints.constrained_nodes())
      anchors.insert(anchors.end(), node.dofs.begin(), node.dofs.end());
    std::sort(anchors.begin(), anchors.end());
    for (unsigned int v = 0; v < fixed.size(); ++v)
      for (const auto dof : fem.dof_map.vertex_dofs[v])
        if (affine.is_constrained(dof) ||
            std::binary_search(anchors.begin(), anchors.end(), dof))
          fixed[v] = true;

    std::vector<Point<dim>> trial     = mesh.get_block_mesh().vertices;
    const auto              increment = fem.dof_map.vertex_values(d);
    for (unsigned int v = 0; v < trial.size(); ++v)
      trial[v] += increment[v];
    auto plan =
      fracture::plan_crack_advance(mesh,
                                   failing,
                                   trial,
                                   parameters.fracture.nonlocal_radius,
                                   fracture_check.get_edges(),
                                   fixed);
    if (!plan.moved.empty())
      {
        // The state goes with the material: the fields at the new
        // positions. The acceleration is carried as a field (M a over the
        // lumped mass of the mesh before the move, which crack_edges()
        // divides by again).
        const std::vector<Point<dim>> old_vertices =
          mesh.get_block_mesh().vertices;
        std::vector<Point<dim>> new_vertices = old_vertices;
        for (unsigned int i = 0; i < plan.moved.size(); ++i)
          new_vertices[plan.moved[i]] = plan.position[i];
        Vector<double> acceleration =
          fem.linear_system.lumped_acceleration(kinematics.inertia_force);
        std::vector<Vector<double> *> fields = {&displacement,
                                                &kinematics.velocity,
                                                &acceleration};
        if (kinematics.acceleration.size() > 0)
          fields.push_back(&kinematics.acceleration);
        state_transfer::interpolate_moved(*fem.fe,
                                          fem.dof_map.cell_dofs,
                                          mesh.get_block_mesh().triangles,
                                          plan.moved,
                                          old_vertices,
                                          new_vertices,
                                          fields);
        kinematics.inertia_force =
          fem.linear_system.lumped_inertia_force(acceleration);
        mesh.relocate_vertices(plan.moved,
                               plan.position,
                               plan.initial_position);
      }
    for (auto &advance : plan.advances)
      {
        advance.time = time;
        tip_advances.push_back(advance);
      }
    return plan.edges;
  }



  template std::vector<std::array<unsigned int, 2>>
  Simulator<2>::check_fracture(const Vector<double> &, const double);
  template void
  Simulator<2>::crack_edges(const std::vector<std::array<unsigned int, 2>> &);
  template std::vector<std::array<unsigned int, 2>>
  Simulator<2>::advance_crack_tips(
    const std::vector<std::array<unsigned int, 2>> &,
    const Vector<double> &);
} // namespace ndda
