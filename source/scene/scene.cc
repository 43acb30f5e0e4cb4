// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/base/expression.h>
#include <ndda/base/utilities.h>
#include <ndda/geometry/block_mesh.h>
#include <ndda/mesh/boundary_edges.h>
#include <ndda/scene/scene.h>
#include <ndda/time/time_integrator.h>

#include <cmath>
#include <memory>

namespace ndda
{
  namespace scene
  {
    namespace
    {
      /**
       * The points where something acts, in this order (the mesh depends
       * on it): point loads, ends of line loads, for every boundary
       * condition its points and (if @p all) the ends of its segments,
       * ends of bolts, and (if @p all) the measure points. With @p all
       * these are the points that become mesh vertices; without, the
       * points where a concentrated force acts (Geometry/Mesh
       * grading/Loaded point mesh size).
       */
      std::vector<Point<2>>
      acting_points(const parameters::Parameters &parameters, const bool all)
      {
        std::vector<Point<2>> points;
        for (const auto &load : parameters.loads.point_loads)
          points.push_back(load.point);
        for (const auto &load : parameters.loads.line_loads)
          {
            points.push_back(load.segment.a);
            points.push_back(load.segment.b);
          }
        for (const auto &bc : parameters.boundary_conditions.conditions)
          {
            points.insert(points.end(), bc.points.begin(), bc.points.end());
            if (all)
              for (const auto &s : bc.segments)
                {
                  points.push_back(s.a);
                  points.push_back(s.b);
                }
          }
        for (const auto &bolt : parameters.bolts.bolts)
          {
            points.push_back(bolt.first);
            points.push_back(bolt.second);
          }
        if (all)
          points.insert(points.end(),
                        parameters.output.measure_points.begin(),
                        parameters.output.measure_points.end());
        return points;
      }
    } // namespace



    void
    build_mesh(const parameters::Parameters   &parameters,
               const dealii::Triangulation<2> *triangulation,
               CrackableMesh                  &mesh)
    {
      const auto &geometry = parameters.geometry;
      if (triangulation != nullptr)
        mesh.build(*triangulation);
      else if (!geometry.mesh_file.empty())
        {
          const auto material_of_tag = [&](const unsigned int tag) {
            for (const auto &[t, name] : geometry.mesh_file_materials)
              if (t == tag)
                return parameters.materials.id(name,
                                               "Geometry/Mesh file materials");
            AssertThrow(geometry.mesh_file_materials.empty(),
                        ExcMessage("Geometry/Mesh file materials: the mesh "
                                   "has physical tag " +
                                   std::to_string(tag) +
                                   ", which is not listed. Give a material "
                                   "for every physical surface."));
            return tag;
          };
          mesh.read_msh(geometry.mesh_file, material_of_tag);
        }
      else
        {
          AssertThrow(!geometry.blocks.empty() || !geometry.regions.empty(),
                      ExcMessage("Geometry: the scene has no blocks. Give "
                                 "'set Blocks = name' with a subsection "
                                 "'name', or Regions, or a Mesh file."));
          geometry::SceneGeometry scene;
          scene.blocks                = geometry.blocks;
          scene.regions               = geometry.regions;
          scene.min_angle             = geometry.min_angle;
          scene.max_cells             = geometry.max_cells;
          scene.snap_tolerance        = geometry.snap_tolerance;
          scene.required_vertices     = acting_points(parameters, true);
          scene.grading               = geometry.grading;
          scene.grading.loaded_points = acting_points(parameters, false);
          mesh.build(geometry::mesh_scene(scene));
        }
      const auto n_materials = parameters.materials.materials.size();
      for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
        AssertThrow(cell->material_id() < n_materials,
                    ExcMessage("Mesh: a cell has material id " +
                               std::to_string(cell->material_id()) +
                               ", but only " + std::to_string(n_materials) +
                               " materials are declared in "
                               "Materials/Names."));
    }



    double
    half_height(const CrackableMesh &mesh)
    {
      const auto box = mesh.bounding_box();
      return 0.5 * std::max(box.second[1] - box.first[1],
                            1e-3 * (box.second[0] - box.first[0]));
    }



    std::vector<parameters::InitialState>
    initial_states(const parameters::Parameters &parameters,
                   const CrackableMesh          &mesh)
    {
      const auto                           &geometry = parameters.geometry;
      std::vector<parameters::InitialState> block_state(mesh.n_blocks());
      const auto                           &names = mesh.get_block_names();
      for (unsigned int b = 0; b < names.size(); ++b)
        {
          for (unsigned int i = 0; i < geometry.blocks.size(); ++i)
            if (geometry.blocks[i].name == names[b])
              block_state[b] = geometry.block_states[i];
          for (unsigned int i = 0; i < geometry.regions.size(); ++i)
            if (names[b].rfind(geometry.regions[i].name + ".", 0) == 0)
              block_state[b] = geometry.region_states[i];
        }
      for (auto &state : block_state)
        if (state.kinematics.empty())
          state.kinematics = parameters.control.kinematics;
      return block_state;
    }



    void
    set_initial_state(const parameters::Parameters &parameters,
                      const CrackableMesh          &mesh,
                      const dealii::DoFHandler<2>  &dof_handler,
                      const dealii::Mapping<2>     &mapping,
                      StressField                  &stresses,
                      dealii::Vector<double>       &velocity)
    {
      const std::vector<parameters::InitialState> block_state =
        initial_states(parameters, mesh);
      std::vector<std::unique_ptr<Expression>> initial_velocity;
      for (const auto &state : block_state)
        initial_velocity.push_back(std::make_unique<Expression>(
          state.velocity, 2, false, state.where + "/Initial velocity"));

      const auto &fe      = dof_handler.get_fe();
      const auto  support = fe.base_element(0).get_unit_support_points();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int b = mesh.block_of_cell(cell->active_cell_index());
          const auto        &s = block_state[b].stress;
          for (auto &sigma : stresses[cell->active_cell_index()])
            {
              sigma[0][0] = s[0];
              sigma[1][1] = s[1];
              sigma[0][1] = s[2];
            }
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto [component, base] = fe.system_to_component_index(i);
              const Point<2> x =
                mapping.transform_unit_to_real_cell(cell, support[base]);
              velocity[dofs[i]] = initial_velocity[b]->value(x, component);
            }
        }
    }



    ContactDistances
    setup_contacts(const parameters::Parameters    &parameters,
                   const CrackableMesh             &mesh,
                   const std::vector<unsigned int> &cell_material,
                   const DofMap                    &dofs,
                   const double                     length,
                   contact::ContactHandler         &contacts)
    {
      const auto &materials   = parameters.materials;
      double      max_modulus = 0;
      for (const auto &m : materials.materials)
        max_modulus = std::max(max_modulus, m.youngs_modulus);

      // The edges index the triangles of the block mesh, which are the
      // active cells of the triangulation, vertex order kept.
      const auto edges = boundary_edges(mesh.get_block_mesh());
      {
        std::vector<Triangulation<2>::active_cell_iterator> cells;
        for (const auto &cell :
             mesh.get_triangulation().active_cell_iterators())
          cells.push_back(cell);
        for (const auto &e : edges)
          AssertThrow(cells[e.cell]->vertex_index(e.local_vertex) == e.v0 &&
                        cells[e.cell]->vertex_index((e.local_vertex + 1) % 3) ==
                          e.v1,
                      ExcInternalError());
      }
      // The friction coefficient of each boundary edge's side: its
      // material's joint friction angle, or the scene's joint angle.
      std::vector<double> edge_friction(edges.size());
      for (unsigned int e = 0; e < edges.size(); ++e)
        {
          const auto  &m = materials.materials[cell_material[edges[e].cell]];
          const double angle = m.joint_friction_angle >= 0. ?
                                 m.joint_friction_angle :
                                 materials.joint.friction_angle;
          edge_friction[e]   = std::tan(angle * numbers::PI / 180.);
        }

      ContactDistances distances;
      distances.detection =
        2. * parameters.control.max_displacement_ratio * length;
      distances.penetration_tolerance =
        parameters.contact.max_penetration_ratio * length;

      contact::ContactSettings settings;
      settings.normal_stiffness =
        parameters.contact.penalty_factor * max_modulus * materials.thickness;
      settings.shear_ratio          = parameters.contact.shear_stiffness_ratio;
      settings.vertex_vertex_method = parameters.contact.vertex_vertex_method;
      settings.state_tolerance      = 1e-9 * distances.penetration_tolerance;
      settings.ignore_depth         = distances.penetration_tolerance;
      settings.bond_tension =
        materials.joint.tensile_strength * materials.thickness;
      settings.bond_cohesion = materials.joint.cohesion * materials.thickness;
      settings.law           = parameters.contact.law;
      settings.start_weight =
        parameters.control.time_integrator->contact_start_weight();
      contacts.initialize(edges, edge_friction, dofs, settings);
      return distances;
    }



    time::StepController::Limits
    step_limits(const parameters::Parameters &parameters)
    {
      time::StepController::Limits limits;
      limits.nominal_step           = parameters.control.time_step;
      limits.end_time               = parameters.control.end_time;
      limits.max_cuts               = parameters.control.max_step_cuts;
      limits.max_displacement_ratio = parameters.control.max_displacement_ratio;
      limits.max_open_close_iterations =
        parameters.contact.max_open_close_iterations;
      return limits;
    }



    contact::OpenCloseSolver::Settings
    open_close_settings(const parameters::Parameters &parameters)
    {
      contact::OpenCloseSolver::Settings settings;
      settings.max_iterations   = parameters.contact.max_open_close_iterations;
      settings.reuse_iterations = parameters.contact.reuse_iterations;
      settings.max_one_way_iterations =
        parameters.contact.max_one_way_iterations;
      settings.contact_start_weight =
        parameters.control.time_integrator->contact_start_weight();
      return settings;
    }
  } // namespace scene
} // namespace ndda
