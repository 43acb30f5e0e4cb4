// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/fracture/edge_failure_check.h>

#include <algorithm>

namespace ndda
{
  namespace fracture
  {
    void
    EdgeFailureCheck::setup(
      const CrackableMesh                        &mesh,
      const std::vector<unsigned int>            &cell_material,
      const std::vector<std::optional<Strength>> &material_strength,
      const std::vector<bool>                    &may_crack,
      const double                                nonlocal_radius)
    {
      edges.clear();
      strength.clear();
      has_nonlocal = false;
      any_material_fractures =
        std::any_of(material_strength.begin(),
                    material_strength.end(),
                    [](const auto &s) { return s.has_value(); });
      if (!any_material_fractures)
        return;
      const auto &block_mesh = mesh.get_block_mesh();
      // Every interior edge that is not a closed crack: where the material
      // is continuous (the nonlocal average passes through these).
      std::vector<InteriorEdge> continuous;
      for (const auto &edge : find_interior_edges(block_mesh.triangles,
                                                  block_mesh.vertices.size()))
        if (!mesh.is_cracked(edge.vertices[0], edge.vertices[1]))
          continuous.push_back(edge);
      for (const auto &edge : continuous)
        {
          if (!may_crack.empty() &&
              (!may_crack[edge.cells[0]] || !may_crack[edge.cells[1]]))
            continue;
          const auto &s0 = material_strength[cell_material[edge.cells[0]]];
          const auto &s1 = material_strength[cell_material[edge.cells[1]]];
          if (!s0 || !s1)
            continue;
          Strength s;
          s.cohesion       = std::min(s0->cohesion, s1->cohesion);
          s.friction_angle = std::min(s0->friction_angle, s1->friction_angle);
          s.tensile_strength =
            std::min(s0->tensile_strength, s1->tensile_strength);
          edges.push_back(edge);
          strength.push_back(s);
        }
      if (nonlocal_radius > 0.)
        {
          // On the initial geometry: the radius is measured in the
          // material, and a row kept after a crack is the row a fresh
          // setup would compute (a resumed run gets the same weights).
          nonlocal.setup(edges,
                         continuous,
                         mesh.get_initial_vertices(),
                         block_mesh.triangles,
                         nonlocal_radius);
          has_nonlocal = true;
        }
    }



    std::vector<std::array<unsigned int, 2>>
    EdgeFailureCheck::check(
      const parameters::Fracture                     &parameters,
      const std::vector<std::array<unsigned int, 3>> &triangles,
      const std::vector<double>                      &cell_area,
      const BlockState                               &start,
      const BlockState                               &end,
      const double                                    time,
      const double                                    dt)
    {
      const auto method = parameters.edge_stress_method;
      const auto states = [&](const BlockState &state) {
        if (method != EdgeStressMethod::nonlocal_average)
          return edge_states(edges,
                             state.vertices,
                             triangles,
                             state.cell_stress,
                             cell_area,
                             method);
        AssertThrow(has_nonlocal,
                    dealii::ExcMessage(
                      "EdgeFailureCheck: the nonlocal edge stress needs a "
                      "positive radius in setup()."));
        return edge_states(edges,
                           state.vertices,
                           nonlocal.apply(state.cell_stress));
      };
      const auto start_states      = states(start);
      const auto end_states        = states(end);
      const bool first_record_done = first.mode != FailureMode::none;
      n_failing                    = 0;
      // The edges that fail, with their failure times (fractions of the
      // step); the earliest ones, within the crack window, crack first.
      std::vector<std::pair<double, unsigned int>> failing;
      for (unsigned int e = 0; e < edges.size(); ++e)
        {
          const EdgeFailure failure =
            parameters.criterion->failure_in_step(start_states[e],
                                                  end_states[e],
                                                  strength[e]);
          if (!failure.fails())
            continue;
          ++n_failing;
          failing.emplace_back(failure.time, e);
          const double t = time + failure.time * dt;
          // The first check that finds failing edges keeps the earliest of
          // them; the re-solves after a crack do not change the record (a
          // crack can make another edge fail earlier within the same
          // step).
          if (!first_record_done &&
              (first.mode == FailureMode::none || t < first.time))
            {
              const auto &v  = edges[e].vertices;
              first.mode     = failure.mode;
              first.time     = t;
              first.location = dealii::Point<2>(
                0.5 * (end.vertices[v[0]] + end.vertices[v[1]]));
            }
        }
      std::vector<std::array<unsigned int, 2>> cracking;
      if (failing.empty())
        return cracking;
      std::sort(failing.begin(), failing.end());
      const double last =
        failing.front().first + parameters.crack_window + 1e-12;
      for (const auto &[t, e] : failing)
        if (t <= last)
          cracking.push_back(edges[e].vertices);
      return cracking;
    }
  } // namespace fracture
} // namespace ndda
