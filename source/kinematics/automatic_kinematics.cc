// SPDX-License-Identifier: GPL-3.0-or-later
//
// Kinematics = auto: the indicator that promotes a block to its mesh and
// demotes it back (doc/theory.md, "Automatic kinematics").

#include <deal.II/base/numbers.h>

#include <ndda/kinematics/automatic_kinematics.h>
#include <ndda/kinematics/block_kinematics.h>

#include <cmath>
#include <map>
#include <tuple>

namespace ndda
{
  namespace kinematics
  {
    using namespace dealii;

    void
    AutomaticSettings::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Automatic kinematics");
      prm.declare_entry(
        "Start model",
        "affine",
        Patterns::Selection("affine|rigid"),
        "The model a block with 'Kinematics = auto' starts with and returns "
        "to when it is demoted (doc/theory.md, \"Automatic kinematics\").");
      prm.declare_entry(
        "Promotion fraction",
        "0.5",
        Patterns::Double(0., 1.),
        "An auto block is promoted to its mesh when one of its stresses "
        "(its mean stress, or the stress next to a contact, from the "
        "contact's traction) comes within this fraction of its material's "
        "fracture criterion: the stress divided by the fraction fails. "
        "Blocks of materials without fracture stay with the start model.");
      prm.declare_entry(
        "Demotion fraction",
        "0.25",
        Patterns::Double(0., 1.),
        "A meshed auto block is unloaded when all its stresses divided by "
        "this fraction are safe; less than the promotion fraction.");
      prm.declare_entry(
        "Demotion steps",
        "100",
        Patterns::Integer(1),
        "A meshed auto block returns to the start model after this many "
        "unloaded steps in a row, unless a crack touches it. Its velocity "
        "and inertia force are then fitted by the start model's (momentum "
        "and angular momentum kept; the energy of its vibration is lost).");
      prm.leave_subsection();
    }



    void
    AutomaticSettings::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Automatic kinematics");
      start_model        = prm.get("Start model");
      promotion_fraction = prm.get_double("Promotion fraction");
      demotion_fraction  = prm.get_double("Demotion fraction");
      demotion_steps     = prm.get_integer("Demotion steps");
      prm.leave_subsection();
      AssertThrow(promotion_fraction > 0.,
                  ExcMessage("Control/Automatic kinematics/Promotion "
                             "fraction: must be greater than zero."));
      AssertThrow(demotion_fraction < promotion_fraction,
                  ExcMessage("Control/Automatic kinematics/Demotion "
                             "fraction (" +
                             std::to_string(demotion_fraction) +
                             ") must be less than the Promotion fraction (" +
                             std::to_string(promotion_fraction) + ")."));
    }



    bool
    near_failure(const fracture::FractureCriterion &criterion,
                 const fracture::Strength          &strength,
                 const SymmetricTensor<2, 2>       &stress,
                 const double                       fraction)
    {
      if (stress.norm() == 0.)
        return false;
      const SymmetricTensor<2, 2> scaled = stress / fraction;
      // The planes: 18 normals 10 degrees apart, the first along the
      // larger principal direction.
      const double first =
        0.5 * std::atan2(2. * scaled[0][1], scaled[0][0] - scaled[1][1]);
      const fracture::EdgeState zero;
      for (unsigned int k = 0; k < 18; ++k)
        {
          const double        angle = first + k * numbers::PI / 18.;
          const Tensor<1, 2>  n({std::cos(angle), std::sin(angle)});
          const Tensor<1, 2>  t({-n[1], n[0]});
          fracture::EdgeState end;
          end.stress        = scaled;
          end.normal_stress = n * (scaled * n);
          end.shear_stress  = t * (scaled * n);
          // From zero to the scaled stress in one step: it fails within
          // the step if the scaled stress is beyond the criterion.
          if (criterion.failure_in_step(zero, end, strength).fails())
            return true;
        }
      return false;
    }



    SymmetricTensor<2, 2>
    boundary_stress(const SymmetricTensor<2, 2> &stress,
                    const Tensor<1, 2>          &normal,
                    const Tensor<1, 2>          &traction)
    {
      const Tensor<1, 2>    e  = traction - stress * normal;
      const double          en = e * normal;
      SymmetricTensor<2, 2> d;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          d[i][j] =
            e[i] * normal[j] + normal[i] * e[j] - en * normal[i] * normal[j];
      return stress + d;
    }



    std::vector<std::vector<std::pair<unsigned int, double>>>
    AutomaticKinematics::side_nodes(const FESystem<2> &fe)
    {
      // Barycentric coordinates on deal.II's reference triangle (0, 0),
      // (1, 0), (0, 1); side i runs from vertex i to vertex i + 1, where
      // the coordinate of vertex i + 2 vanishes. A vertex (two vanishing
      // coordinates) is shared by two sides.
      const auto &points = fe.base_element(0).get_unit_support_points();
      std::vector<std::vector<std::pair<unsigned int, double>>> nodes(3);
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          const double lambda[3] = {1. - points[k][0] - points[k][1],
                                    points[k][0],
                                    points[k][1]};
          unsigned int zeros     = 0;
          for (const double l : lambda)
            zeros += std::abs(l) < 1e-12 ? 1 : 0;
          for (unsigned int i = 0; i < 3; ++i)
            if (std::abs(lambda[(i + 2) % 3]) < 1e-12)
              nodes[i].emplace_back(k, zeros == 2 ? 0.5 : 1.);
        }
      return nodes;
    }



    void
    AutomaticKinematics::mark_cracked(const std::vector<unsigned int> &cells)
    {
      for (const unsigned int c : cells)
        {
          if (c >= cell_cracked.size())
            cell_cracked.resize(c + 1, false);
          cell_cracked[c] = true;
        }
    }



    void
    AutomaticKinematics::setup(
      const CrackableMesh                                  &mesh,
      const FESystem<2>                                    &fe,
      const DofMap                                         &dofs,
      const std::vector<bool>                              &cell_auto,
      const std::vector<std::optional<fracture::Strength>> &strength,
      const AutomaticSettings                              &settings_in)
    {
      settings      = settings_in;
      dof_map       = &dofs;
      cell_strength = strength;
      cell_cracked.resize(cell_auto.size(), false);
      const auto        &block_mesh = mesh.get_block_mesh();
      const unsigned int n_blocks   = mesh.n_blocks();
      block_auto.assign(n_blocks, false);
      block_cracked.assign(n_blocks, false);
      // A crack keeps the index of every block and appends the new ones.
      unloaded_steps.resize(n_blocks, 0);
      for (unsigned int c = 0; c < cell_auto.size(); ++c)
        {
          const unsigned int b = mesh.block_of_cell(c);
          block_auto[b]        = block_auto[b] || cell_auto[c];
          block_cracked[b]     = block_cracked[b] || cell_cracked[c];
        }
      any_auto = std::find(block_auto.begin(), block_auto.end(), true) !=
                 block_auto.end();
      edges.clear();
      if (!any_auto)
        return;

      // The boundary edges of the auto blocks, with the nodes on each and
      // their shares (a vertex is shared by two boundary edges).
      const auto sides = side_nodes(fe);
      std::map<std::tuple<double, double, double, double>, unsigned int> faces;
      for (const BoundaryEdge &e : boundary_edges(block_mesh))
        {
          const Point<2> &a = block_mesh.vertices[e.v0];
          const Point<2> &b = block_mesh.vertices[e.v1];
          // A slit: the two faces of a crack that ends inside the block
          // lie on one another, in the same block.
          const auto twin = faces.find({b[0], b[1], a[0], a[1]});
          if (twin != faces.end() && twin->second == e.block)
            block_cracked[e.block] = true;
          faces[{a[0], a[1], b[0], b[1]}] = e.block;
          if (!block_auto[e.block])
            continue;
          Edge        edge{e.v0, e.v1, e.cell, e.block, {}, {}};
          const auto *cell_dofs = dofs.dofs_of_cell(e.cell);
          for (const auto &[k, share] : sides[e.local_vertex])
            {
              const auto dof = cell_dofs[fe.component_to_system_index(0, k)];
              edge.nodes.push_back(dofs.dof_to_node[dof]);
              edge.share.push_back(share);
            }
          edges.push_back(std::move(edge));
        }
    }



    std::vector<bool>
    AutomaticKinematics::stressed(const CrackableMesh               &mesh,
                                  const fracture::FractureCriterion &criterion,
                                  const BlockStresses               &state,
                                  const std::vector<bool>           &meshed,
                                  const bool                         of_meshed,
                                  const double fraction) const
    {
      const unsigned int n_blocks = block_auto.size();
      std::vector<bool>  result(n_blocks, false);
      // The blocks looked at, the stress of each reduced one (its
      // area-weighted mean) and the strength of each (the first strength
      // of its cells).
      std::vector<bool> looked_at(n_blocks);
      for (unsigned int b = 0; b < n_blocks; ++b)
        looked_at[b] = block_auto[b] && meshed[b] == of_meshed;
      std::vector<SymmetricTensor<2, 2>>             mean(n_blocks);
      std::vector<double>                            area(n_blocks, 0.);
      std::vector<std::optional<fracture::Strength>> strength(n_blocks);
      const auto check = [&](const unsigned int           b,
                             const SymmetricTensor<2, 2> &stress) {
        if (!result[b])
          result[b] = near_failure(criterion, *strength[b], stress, fraction);
      };
      for (unsigned int c = 0; c < state.cell_stress.size(); ++c)
        {
          const unsigned int b = mesh.block_of_cell(c);
          if (!looked_at[b] || !cell_strength[c])
            continue;
          if (!strength[b])
            strength[b] = cell_strength[c];
          mean[b] += state.cell_area[c] * state.cell_stress[c];
          area[b] += state.cell_area[c];
          if (meshed[b])
            check(b, state.cell_stress[c]);
        }
      for (unsigned int b = 0; b < n_blocks; ++b)
        if (strength[b] && !meshed[b])
          {
            mean[b] /= area[b];
            check(b, mean[b]);
          }
      if (state.contact_force.size() == 0)
        return result;

      // The contact tractions on the boundary edges.
      const auto &vertices = mesh.get_block_mesh().vertices;
      for (const Edge &e : edges)
        {
          if (!strength[e.block] || result[e.block])
            continue;
          Tensor<1, 2> force;
          for (unsigned int i = 0; i < e.nodes.size(); ++i)
            for (unsigned int d = 0; d < 2; ++d)
              force[d] +=
                e.share[i] *
                state.contact_force[dof_map->node_dofs[e.nodes[i]][d]];
          if (force.norm() == 0.)
            continue;
          const Tensor<1, 2> side   = vertices[e.v1] - vertices[e.v0];
          const double       length = side.norm();
          const Tensor<1, 2> normal({side[1] / length, -side[0] / length});
          check(e.block,
                boundary_stress(meshed[e.block] ? state.cell_stress[e.cell] :
                                                  mean[e.block],
                                normal,
                                force / (length * state.thickness)));
        }
      return result;
    }



    std::vector<unsigned int>
    AutomaticKinematics::promotions(
      const CrackableMesh               &mesh,
      const fracture::FractureCriterion &criterion,
      const BlockStresses               &state,
      const std::vector<bool>           &meshed,
      const bool                         count)
    {
      const auto near = stressed(
        mesh, criterion, state, meshed, false, settings.promotion_fraction);
      std::vector<unsigned int> promote;
      for (unsigned int b = 0; b < block_auto.size(); ++b)
        if (block_auto[b] && !meshed[b] && near[b])
          promote.push_back(b);
      if (count)
        n_promoted += promote.size();
      return promote;
    }



    std::vector<unsigned int>
    AutomaticKinematics::demotions(const CrackableMesh               &mesh,
                                   const fracture::FractureCriterion &criterion,
                                   const BlockStresses               &state,
                                   const std::vector<bool>           &meshed)
    {
      const auto loaded = stressed(
        mesh, criterion, state, meshed, true, settings.demotion_fraction);
      std::vector<unsigned int> demote;
      for (unsigned int b = 0; b < block_auto.size(); ++b)
        {
          if (!block_auto[b] || !meshed[b] || loaded[b] || block_cracked[b])
            {
              unloaded_steps[b] = 0;
              continue;
            }
          if (++unloaded_steps[b] >= settings.demotion_steps)
            {
              demote.push_back(b);
              unloaded_steps[b] = 0;
            }
        }
      n_demoted += demote.size();
      return demote;
    }
  } // namespace kinematics
} // namespace ndda
