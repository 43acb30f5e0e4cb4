// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <deal.II/numerics/data_out.h>

#include <ndda/fracture/edge_stress.h>
#include <ndda/mesh/state_transfer.h>
#include <ndda/simulator.h>

#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace ndda
{
  namespace
  {
    /** A stream buffer that writes to two buffers (console and log). */
    class TeeBuffer : public std::streambuf
    {
    public:
      TeeBuffer(std::streambuf *a, std::streambuf *b)
        : a(a)
        , b(b)
      {}

    protected:
      int
      overflow(int c) override
      {
        if (c == EOF)
          return !EOF;
        const int ra = a->sputc(c), rb = b->sputc(c);
        return (ra == EOF || rb == EOF) ? EOF : c;
      }
      int
      sync() override
      {
        return (a->pubsync() == 0 && b->pubsync() == 0) ? 0 : -1;
      }

    private:
      std::streambuf *a, *b;
    };

    std::string
    to_string(const Point<2> &p)
    {
      std::ostringstream out;
      out << "(" << p[0] << ", " << p[1] << ")";
      return out.str();
    }

    double
    distance_to_segment(const Point<2> &p, const geometry::Segment &s)
    {
      const Tensor<1, 2> ab = s.b - s.a;
      const double t = std::clamp(((p - s.a) * ab) / ab.norm_square(), 0., 1.);
      return p.distance(s.a + t * ab);
    }

    std::unique_ptr<FunctionParser<2>>
    make_function(const std::string &expression,
                  const unsigned int n_components,
                  const bool         time_dependent)
    {
      auto function = std::make_unique<FunctionParser<2>>(n_components);
      function->initialize(time_dependent ? "x,y,t" : "x,y",
                           expression,
                           {{"pi", numbers::PI}},
                           time_dependent);
      return function;
    }

    /** cos and sin of a small angle, by series where that is exact. */
    std::pair<double, double>
    cos_sin(const double omega)
    {
      if (std::abs(omega) > 1e-2)
        return {std::cos(omega), std::sin(omega)};
      // Truncation below 1e-15 for |omega| <= 1e-2.
      const double w2 = omega * omega;
      return {1. - w2 / 2. * (1. - w2 / 12. * (1. - w2 / 30.)),
              omega * (1. - w2 / 6. * (1. - w2 / 20.))};
    }

    /** Rotate the 2D vector stored at dofs (i, j) by the angle omega. */
    void
    rotate_pair(Vector<double>               &v,
                const types::global_dof_index i,
                const types::global_dof_index j,
                const double                  c,
                const double                  s)
    {
      const double x = v[i], y = v[j];
      v[i] = c * x - s * y;
      v[j] = s * x + c * y;
    }
  } // namespace



  template <int dim>
  Simulator<dim>::Simulator(const std::string &parameter_file)
    : console(std::cout.rdbuf())
    , pcout(console, true)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , mapping(linear_mapping())
    , dof_handler(mesh.get_triangulation())
  {
    parameters.read_file(parameter_file, prm);
    parameters_from_file = true;
  }



  template <int dim>
  Simulator<dim>::Simulator(const parameters::Parameters &parameters,
                            const Triangulation<dim>     *triangulation)
    : parameters(parameters)
    , console(std::cout.rdbuf())
    , pcout(console, true)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , mapping(linear_mapping())
    , dof_handler(mesh.get_triangulation())
  {
    if (triangulation != nullptr)
      {
        user_triangulation = std::make_unique<Triangulation<dim>>();
        user_triangulation->copy_triangulation(*triangulation);
      }
  }



  template <int dim>
  Simulator<dim>::~Simulator()
  {
    dof_handler.clear();
    console.rdbuf(std::cout.rdbuf());
  }



  template <int dim>
  void
  Simulator<dim>::make_mesh(const Triangulation<dim> *triangulation)
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
        scene.blocks    = geometry.blocks;
        scene.regions   = geometry.regions;
        scene.min_angle = geometry.min_angle;
        // Every point where something acts becomes a mesh vertex.
        auto &required = scene.required_vertices;
        for (const auto &load : parameters.loads.point_loads)
          required.push_back(load.point);
        for (const auto &load : parameters.loads.line_loads)
          {
            required.push_back(load.segment.a);
            required.push_back(load.segment.b);
          }
        for (const auto &bc : parameters.boundary_conditions.conditions)
          {
            required.insert(required.end(), bc.points.begin(), bc.points.end());
            for (const auto &s : bc.segments)
              {
                required.push_back(s.a);
                required.push_back(s.b);
              }
          }
        for (const auto &bolt : parameters.bolts.bolts)
          {
            required.push_back(bolt.first);
            required.push_back(bolt.second);
          }
        required.insert(required.end(),
                        parameters.output.measure_points.begin(),
                        parameters.output.measure_points.end());
        mesh.build(geometry::mesh_scene(scene));
      }
    for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
      AssertThrow(cell->material_id() < parameters.materials.materials.size(),
                  ExcMessage(
                    "Mesh: a cell has material id " +
                    std::to_string(cell->material_id()) + ", but only " +
                    std::to_string(parameters.materials.materials.size()) +
                    " materials are declared in Materials/Names."));
  }



  template <int dim>
  void
  Simulator<dim>::setup()
  {
    TimerOutput::Scope scope(timer, "setup");
    make_mesh(user_triangulation.get());
    const auto box    = mesh.bounding_box();
    scene_half_height = 0.5 * std::max(box.second[1] - box.first[1],
                                       1e-3 * (box.second[0] - box.first[0]));

    setup_dofs();
    setup_constraints();
    setup_contacts();
    setup_fracture();
    setup_loads();
    setup_measure_points();

    // Initial state: stress and velocity per block.
    const unsigned int n_q = element_cache.n_quadrature_points();
    stress.assign(mesh.get_triangulation().n_active_cells(),
                  std::vector<SymmetricTensor<2, dim>>(n_q));
    std::vector<parameters::InitialState> block_state(mesh.n_blocks());
    const auto                           &names = mesh.get_block_names();
    for (unsigned int b = 0; b < names.size(); ++b)
      {
        for (unsigned int i = 0; i < parameters.geometry.blocks.size(); ++i)
          if (parameters.geometry.blocks[i].name == names[b])
            block_state[b] = parameters.geometry.block_states[i];
        for (unsigned int i = 0; i < parameters.geometry.regions.size(); ++i)
          if (names[b].rfind(parameters.geometry.regions[i].name + ".", 0) == 0)
            block_state[b] = parameters.geometry.region_states[i];
      }
    std::vector<std::unique_ptr<FunctionParser<dim>>> initial_velocity;
    for (const auto &state : block_state)
      initial_velocity.push_back(make_function(state.velocity, dim, false));

    const auto &fe_ref  = *fe;
    const auto  support = fe_ref.base_element(0).get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe_ref.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int b = mesh.block_of_cell(cell->active_cell_index());
        const auto        &s = block_state[b].stress;
        for (auto &sigma : stress[cell->active_cell_index()])
          {
            sigma[0][0] = s[0];
            sigma[1][1] = s[1];
            sigma[0][1] = s[2];
          }
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto [component, base] = fe_ref.system_to_component_index(i);
            const Point<dim> x =
              mapping.transform_unit_to_real_cell(cell, support[base]);
            velocity[dofs[i]] = initial_velocity[b]->value(x, component);
          }
      }

    compute_internal_force();
    is_set_up = true;
  }



  template <int dim>
  void
  Simulator<dim>::setup_dofs(const bool element_matrices)
  {
    // The element by name and what travels with it (physics/finite_element.h).
    auto element = make_element(parameters.control.finite_element);
    fe           = std::move(element.system);
    face_quadrature =
      std::make_unique<Quadrature<dim - 1>>(element.face_quadrature);
    element_cache.set_quadratures(element.cell_quadrature,
                                  element.mass_quadrature);
    n_output_subdivisions = element.n_output_subdivisions;
    dof_handler.distribute_dofs(*fe);
    cell_material.resize(mesh.get_triangulation().n_active_cells());
    for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
      cell_material[cell->active_cell_index()] = cell->material_id();

    // Index caches for the loops of the time step: deal.II's iterators and
    // get_dof_indices() cost more than the arithmetic of a P1 cell.
    const unsigned int n_dofs_per_cell = fe->n_dofs_per_cell();
    cell_dof_indices.resize(mesh.get_triangulation().n_active_cells() *
                            n_dofs_per_cell);
    local_component.resize(n_dofs_per_cell);
    for (unsigned int i = 0; i < n_dofs_per_cell; ++i)
      local_component[i] = fe->system_to_component_index(i).first;
    vertex_dofs.resize(mesh.get_triangulation().n_vertices());
    dof_to_node.assign(dof_handler.n_dofs(), numbers::invalid_unsigned_int);
    node_dofs.clear();
    std::vector<types::global_dof_index> dofs(n_dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(),
                  dofs.end(),
                  cell_dof_indices.begin() +
                    cell->active_cell_index() * n_dofs_per_cell);
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          for (unsigned int c = 0; c < dim; ++c)
            vertex_dofs[cell->vertex_index(v)][c] =
              cell->vertex_dof_index(v, c);
        for (unsigned int i = 0; i < n_dofs_per_cell; ++i)
          {
            const auto [component, base] = fe->system_to_component_index(i);
            if (component == 0 &&
                dof_to_node[dofs[i]] == numbers::invalid_unsigned_int)
              {
                const auto j = dofs[fe->component_to_system_index(1, base)];
                dof_to_node[dofs[i]] = dof_to_node[j] = node_dofs.size();
                node_dofs.push_back({{dofs[i], j}});
              }
          }
      }

    const unsigned int n = dof_handler.n_dofs();
    displacement.reinit(n);
    velocity.reinit(n);
    inertia_force.reinit(n);
    internal_force.reinit(n);
    for (unsigned int d = 0; d < dim; ++d)
      gravity_load[d].reinit(n);

    if (element_matrices)
      element_cache.update(
        dof_handler, mapping, parameters.materials, false, 0.);
    double max_modulus = 0;
    for (const auto &m : parameters.materials.materials)
      max_modulus = std::max(max_modulus, m.youngs_modulus);
    penalty_stiffness = parameters.control.penalty_factor * max_modulus *
                        parameters.materials.thickness;
    linear_solver =
      std::make_unique<LinearSolver>(parameters.control.linear_solver,
                                     parameters.control.solver_tolerance);
  }



  template <int dim>
  unsigned int
  Simulator<dim>::find_vertex(const Point<dim>  &p,
                              const std::string &entry) const
  {
    const auto  &vertices = mesh.get_block_mesh().vertices;
    const auto   box      = mesh.bounding_box();
    const double tolerance =
      1e-8 * std::max(1., box.first.distance(box.second));
    unsigned int best          = numbers::invalid_unsigned_int;
    double       best_distance = tolerance;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (vertices[v].distance(p) <= best_distance)
        {
          best          = v;
          best_distance = vertices[v].distance(p);
        }
    if (best == numbers::invalid_unsigned_int)
      {
        // Outside, or inside but not a vertex (possible for imported meshes).
        AssertThrow(mesh.locate(p).first != numbers::invalid_unsigned_int,
                    ExcMessage(entry + ": the point " + to_string(p) +
                               " lies outside every block. Move it into "
                               "or onto a block."));
        AssertThrow(false,
                    ExcMessage(entry + ": the point " + to_string(p) +
                               " is not a vertex of the mesh. With an "
                               "imported mesh, give points that are mesh "
                               "vertices."));
      }
    return best;
  }



  template <int dim>
  void
  Simulator<dim>::setup_constraints()
  {
    // Which two dofs belong to the same node: per vertex dof of component 0
    // the dof of component 1 at the same support point.
    const auto                          &fe_ref = *fe;
    std::vector<types::global_dof_index> partner(dof_handler.n_dofs());
    std::vector<unsigned int>            component(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(fe_ref.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto [c, base] = fe_ref.system_to_component_index(i);
            component[dofs[i]]   = c;
            if (c == 0)
              {
                const unsigned int j =
                  fe_ref.component_to_system_index(1, base);
                partner[dofs[i]] = dofs[j];
                partner[dofs[j]] = dofs[i];
              }
          }
      }
    std::vector<Point<dim>> support_points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);
    if (parameters.control.linear_solver == parameters::LinearSolver::cg_amg)
      linear_solver->set_rigid_body_modes(support_points, component);

    // Boundary nodes, for constraints on segments.
    std::vector<bool> on_boundary(dof_handler.n_dofs(), false);
    std::vector<types::global_dof_index> face_dofs(fe_ref.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (unsigned int f = 0; f < cell->n_faces(); ++f)
        if (cell->at_boundary(f))
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (const auto dof : face_dofs)
              on_boundary[dof] = true;
          }

    const auto   box = mesh.bounding_box();
    const double tolerance =
      1e-8 * std::max(1., box.first.distance(box.second));

    node_constraints.clear();
    constraint_functions.clear();
    std::vector<bool> constrained(dof_handler.n_dofs(), false);
    for (const auto &bc : parameters.boundary_conditions.conditions)
      {
        const std::string where    = "Boundary conditions/" + bc.name;
        unsigned int      function = numbers::invalid_unsigned_int;
        if (bc.type != parameters::ConstraintType::fixed)
          {
            function = constraint_functions.size();
            constraint_functions.push_back(
              make_function(bc.value,
                            bc.type == parameters::ConstraintType::roller ? 1 :
                                                                            dim,
                            true));
          }
        const double   angle = bc.roller_angle * numbers::PI / 180.;
        Tensor<1, dim> normal;
        normal[0] = -std::sin(angle);
        normal[1] = std::cos(angle);

        std::vector<types::global_dof_index> nodes;
        for (const auto &p : bc.points)
          {
            const unsigned int vertex = find_vertex(p, where + "/Points");
            const Point<dim>   x      = mesh.get_block_mesh().vertices[vertex];
            for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
              if (component[i] == 0 &&
                  support_points[i].distance(x) <= tolerance)
                nodes.push_back(i);
          }
        for (const auto &segment : bc.segments)
          {
            const unsigned int before = nodes.size();
            for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
              if (component[i] == 0 && on_boundary[i] &&
                  distance_to_segment(support_points[i], segment) <= tolerance)
                nodes.push_back(i);
            AssertThrow(nodes.size() > before,
                        ExcMessage(where +
                                   "/Segments: no boundary vertex "
                                   "lies on the segment " +
                                   to_string(segment.a) + " - " +
                                   to_string(segment.b) +
                                   ". Give a segment along a block's "
                                   "boundary."));
          }
        for (const auto i : nodes)
          {
            if (constrained[i])
              continue; // The first condition listed for a node wins.
            constrained[i] = constrained[partner[i]] = true;
            NodeConstraint nc;
            nc.dofs     = {{i, partner[i]}};
            nc.position = support_points[i];
            nc.type     = bc.type;
            nc.normal   = normal;
            nc.function = function;
            nc.name     = bc.name;
            node_constraints.push_back(nc);
          }
      }

    constraints.clear();
    if (parameters.control.constraint_method ==
        parameters::ConstraintMethod::exact)
      for (const auto &nc : node_constraints)
        {
          if (nc.type != parameters::ConstraintType::roller)
            {
              constraints.add_line(nc.dofs[0]);
              constraints.add_line(nc.dofs[1]);
            }
          else
            {
              // n . u = d: solve for the component with the larger normal
              // entry; the inhomogeneity is handled by the step's
              // prescribed increment (see try_time_step()).
              const unsigned int k =
                std::abs(nc.normal[1]) >= std::abs(nc.normal[0]) ? 1 : 0;
              constraints.add_line(nc.dofs[k]);
              constraints.add_entry(nc.dofs[k],
                                    nc.dofs[1 - k],
                                    -nc.normal[1 - k] / nc.normal[k]);
            }
        }
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, true);
    // Bolts couple two nodes that may lie in different blocks.
    bolts.clear();
    for (const auto &b : parameters.bolts.bolts)
      {
        const std::string where = "Bolts/" + b.name + "/End points";
        Bolt              bolt;
        const Point<dim>  ends[2] = {b.first, b.second};
        for (unsigned int e = 0; e < 2; ++e)
          {
            const Point<dim> x =
              mesh.get_block_mesh().vertices[find_vertex(ends[e], where)];
            bool found = false;
            for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
              if (component[i] == 0 &&
                  support_points[i].distance(x) <= tolerance)
                {
                  bolt.dofs[2 * e]     = i;
                  bolt.dofs[2 * e + 1] = partner[i];
                  found                = true;
                  break;
                }
            AssertThrow(found, ExcInternalError());
          }
        bolt.first      = b.first;
        bolt.second     = b.second;
        bolt.stiffness  = b.stiffness;
        bolt.pretension = b.pretension;
        for (const auto i : bolt.dofs)
          for (const auto j : bolt.dofs)
            dsp.add(i, j);
        bolts.push_back(bolt);
      }
    if (parameters.contact.enabled)
      base_sparsity.copy_from(dsp);
    reinit_matrices(dsp);
    pattern_couplings.clear();
  }



  template <int dim>
  void
  Simulator<dim>::reinit_matrices(DynamicSparsityPattern &dsp)
  {
    constraints.condense(dsp);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
    mass_matrix.reinit(sparsity_pattern);
    damping_matrix.reinit(sparsity_pattern);
    system_matrix.reinit(sparsity_pattern);
    condensed_matrix.reinit(sparsity_pattern);
  }



  template <int dim>
  void
  Simulator<dim>::setup_contacts()
  {
    if (!parameters.contact.enabled)
      return;
    const auto &materials   = parameters.materials;
    double      max_modulus = 0;
    for (const auto &m : materials.materials)
      max_modulus = std::max(max_modulus, m.youngs_modulus);

    // The friction coefficient of each boundary edge's side: its
    // material's joint friction angle, or the scene's joint angle.
    const auto edges = contact::boundary_edges(mesh.get_block_mesh());
    // The edges index the triangles of the block mesh, which are the
    // active cells of the triangulation, vertex order kept.
    {
      std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
      for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
        cells.push_back(cell);
      for (const auto &e : edges)
        AssertThrow(cells[e.cell]->vertex_index(e.local_vertex) == e.v0 &&
                      cells[e.cell]->vertex_index((e.local_vertex + 1) % 3) ==
                        e.v1,
                    ExcInternalError());
    }
    std::vector<double> edge_friction(edges.size());
    for (unsigned int e = 0; e < edges.size(); ++e)
      {
        const auto  &m     = materials.materials[cell_material[edges[e].cell]];
        const double angle = m.joint_friction_angle >= 0. ?
                               m.joint_friction_angle :
                               materials.joint.friction_angle;
        edge_friction[e]   = std::tan(angle * numbers::PI / 180.);
      }

    contact::DofAccess access;
    access.fe          = fe.get();
    access.cell_dofs   = &cell_dof_indices;
    access.component   = &local_component;
    access.vertex_dofs = &vertex_dofs;

    // Shi's detection distance: twice the largest displacement a step may
    // have, so every contact a step can close is a candidate of that step.
    contact_threshold =
      2. * parameters.control.max_displacement_ratio * scene_half_height;
    penetration_tolerance =
      parameters.contact.max_penetration_ratio * scene_half_height;

    contact::ContactSettings settings;
    settings.normal_stiffness =
      parameters.contact.penalty_factor * max_modulus * materials.thickness;
    settings.shear_ratio          = parameters.contact.shear_stiffness_ratio;
    settings.vertex_vertex_method = parameters.contact.vertex_vertex_method;
    settings.state_tolerance      = 1e-9 * penetration_tolerance;
    settings.ignore_depth         = penetration_tolerance;
    settings.bond_tension =
      materials.joint.tensile_strength * materials.thickness;
    settings.bond_cohesion = materials.joint.cohesion * materials.thickness;
    settings.average_start_and_end = parameters.control.time_integrator ==
                                       parameters::TimeIntegrator::newmark &&
                                     parameters.control.analysis_type !=
                                       parameters::AnalysisType::quasi_static;
    contacts.initialize(edges, edge_friction, access, settings);
  }



  template <int dim>
  void
  Simulator<dim>::update_sparsity_for_contacts()
  {
    // The pattern holds the couplings of every candidate contact of the
    // step and those of earlier steps: it (and every matrix on it) is
    // rebuilt only when a coupling is missing, with the union of both
    // sets, so that candidates which come and go near the detection
    // distance do not change it and the direct solver keeps its symbolic
    // analysis (UMFPACK) or its pivot order (KLU). When the pattern holds
    // more than twice the couplings in use, it is rebuilt with the
    // present ones only.
    const auto &couplings = contacts.get_couplings();
    if (std::includes(pattern_couplings.begin(),
                      pattern_couplings.end(),
                      couplings.begin(),
                      couplings.end()) &&
        pattern_couplings.size() <= 2 * couplings.size() + 16)
      return;
    std::vector<std::pair<unsigned int, unsigned int>> merged;
    std::set_union(pattern_couplings.begin(),
                   pattern_couplings.end(),
                   couplings.begin(),
                   couplings.end(),
                   std::back_inserter(merged));
    if (merged.size() > 2 * couplings.size() + 16)
      merged = couplings;
    TimerOutput::Scope                   scope(timer, "sparsity");
    DynamicSparsityPattern               dsp(base_sparsity.n_rows());
    std::vector<types::global_dof_index> row;
    for (types::global_dof_index i = 0; i < base_sparsity.n_rows(); ++i)
      {
        row.clear();
        for (auto entry = base_sparsity.begin(i); entry != base_sparsity.end(i);
             ++entry)
          row.push_back(entry->column());
        dsp.add_entries(i, row.begin(), row.end());
      }
    const unsigned int n_cell_dofs = fe->n_dofs_per_cell();
    for (const auto &[vertex, cell] : merged)
      for (const auto i : vertex_dofs[vertex])
        for (unsigned int k = 0; k < n_cell_dofs; ++k)
          {
            const auto j = cell_dof_indices[cell * n_cell_dofs + k];
            dsp.add(i, j);
            dsp.add(j, i);
          }
    reinit_matrices(dsp);
    pattern_couplings.swap(merged);
    assemble_global_matrices();
  }



  template <int dim>
  typename Simulator<dim>::PointEvaluator
  Simulator<dim>::make_point_evaluator(const Point<dim>  &p,
                                       const std::string &entry) const
  {
    // deal.II 9.4's find_active_cell_around_point() can return a cell of
    // another block on meshes of disconnected blocks; locate by
    // barycentric coordinates instead.
    const auto [cell_index, unit_point] = mesh.locate(p);
    AssertThrow(cell_index != numbers::invalid_unsigned_int,
                ExcMessage(entry + ": the point " + to_string(p) +
                           " lies outside every block. Move it into or onto "
                           "a block."));
    PointEvaluator evaluator;
    evaluator.cell = cell_index;
    evaluator.dofs.assign(cell_dof_indices.begin() +
                            cell_index * fe->n_dofs_per_cell(),
                          cell_dof_indices.begin() +
                            (cell_index + 1) * fe->n_dofs_per_cell());
    for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
      {
        evaluator.shape_values.push_back(fe->shape_value(i, unit_point));
        evaluator.component.push_back(fe->system_to_component_index(i).first);
      }
    return evaluator;
  }



  template <int dim>
  void
  Simulator<dim>::setup_loads()
  {
    gravity = make_function(parameters.loads.gravity, dim, true);
    point_load_functions.clear();
    point_load_points.clear();
    for (const auto &load : parameters.loads.point_loads)
      {
        point_load_functions.push_back(make_function(load.force, dim, true));
        point_load_points.push_back(
          make_point_evaluator(load.point, "Loads/" + load.name + "/Point"));
      }

    line_load_functions.clear();
    loaded_faces.clear();
    const auto   box = mesh.bounding_box();
    const double tolerance =
      1e-8 * std::max(1., box.first.distance(box.second));
    for (unsigned int l = 0; l < parameters.loads.line_loads.size(); ++l)
      {
        const auto &load = parameters.loads.line_loads[l];
        line_load_functions.push_back(
          make_function(load.value, load.is_pressure ? 1 : dim, true));
        unsigned int n_faces = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (unsigned int f = 0; f < cell->n_faces(); ++f)
            if (cell->at_boundary(f) &&
                distance_to_segment(cell->face(f)->vertex(0), load.segment) <=
                  tolerance &&
                distance_to_segment(cell->face(f)->vertex(1), load.segment) <=
                  tolerance)
              {
                LoadedFace face;
                face.line_load = l;
                face.cell      = cell->active_cell_index();
                face.face      = f;
                loaded_faces.push_back(face);
                ++n_faces;
              }
        AssertThrow(n_faces > 0,
                    ExcMessage("Loads/" + load.name +
                               "/Segment: no boundary edge lies on the "
                               "segment " +
                               to_string(load.segment.a) + " - " +
                               to_string(load.segment.b) +
                               ". Give a segment along a block's boundary."));
      }
    update_loaded_faces();
  }



  template <int dim>
  void
  Simulator<dim>::update_loaded_faces()
  {
    // Quadrature data of the loaded faces on the current geometry.
    FEFaceValues<dim> fe_face_values(mapping,
                                     *fe,
                                     *face_quadrature,
                                     update_values | update_JxW_values |
                                       update_normal_vectors |
                                       update_quadrature_points);
    std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      cells.push_back(cell);
    for (auto &face : loaded_faces)
      {
        const auto &cell = cells[face.cell];
        fe_face_values.reinit(cell, face.face);
        face.dofs.resize(fe->n_dofs_per_cell());
        cell->get_dof_indices(face.dofs);
        face.component.clear();
        face.weighted_shape.clear();
        face.points.clear();
        face.normals.clear();
        for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
          face.component.push_back(fe->system_to_component_index(i).first);
        for (unsigned int q = 0; q < face_quadrature->size(); ++q)
          {
            std::vector<double> w(fe->n_dofs_per_cell());
            for (unsigned int i = 0; i < w.size(); ++i)
              w[i] =
                fe_face_values.shape_value_component(i, q, face.component[i]) *
                fe_face_values.JxW(q) * parameters.materials.thickness;
            face.weighted_shape.push_back(w);
            face.points.push_back(fe_face_values.quadrature_point(q));
            face.normals.push_back(fe_face_values.normal_vector(q));
          }
      }
  }



  template <int dim>
  void
  Simulator<dim>::setup_measure_points()
  {
    measure_points.clear();
    for (const auto &p : parameters.output.measure_points)
      measure_points.push_back(
        make_point_evaluator(p, "Output/Measure points"));
    measure_histories.assign(measure_points.size(), {});
  }



  template <int dim>
  std::pair<std::array<Point<dim>, 2>, Tensor<1, dim>>
  Simulator<dim>::bolt_geometry(const Bolt &bolt) const
  {
    std::array<Point<dim>, 2> x = {{bolt.first, bolt.second}};
    for (unsigned int e = 0; e < 2; ++e)
      for (unsigned int d = 0; d < dim; ++d)
        x[e][d] += displacement[bolt.dofs[dim * e + d]];
    return {x, (x[0] - x[1]) / x[0].distance(x[1])};
  }



  template <int dim>
  void
  Simulator<dim>::assemble_global_matrices()
  {
    stiffness_matrix                            = 0;
    mass_matrix                                 = 0;
    damping_matrix                              = 0;
    has_damping                                 = false;
    const unsigned int                   n_dofs = fe->n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n_dofs);
    for (unsigned int c = 0; c < cell_dof_indices.size() / n_dofs; ++c)
      {
        const auto &data = element_cache[c];
        std::copy(&cell_dof_indices[c * n_dofs],
                  &cell_dof_indices[c * n_dofs] + n_dofs,
                  dofs.begin());
        stiffness_matrix.add(dofs, data.stiffness);
        mass_matrix.add(dofs, data.mass);
        if (data.viscosity_over_density > 0)
          {
            has_damping = true;
            for (unsigned int i = 0; i < dofs.size(); ++i)
              for (unsigned int j = 0; j < dofs.size(); ++j)
                damping_matrix.add(dofs[i],
                                   dofs[j],
                                   data.viscosity_over_density *
                                     data.mass(i, j));
          }
      }

    // Bolts, thesis 3.6: k_b L L^T with L the unit vector between the
    // anchors on the current geometry.
    for (const auto &bolt : bolts)
      {
        const Tensor<1, dim> l = bolt_geometry(bolt).second;
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                stiffness_matrix.add(bolt.dofs[2 * a + i],
                                     bolt.dofs[2 * b + j],
                                     (a == b ? 1. : -1.) * bolt.stiffness *
                                       l[i] * l[j]);
      }
    matrices_changed = true;
  }



  template <int dim>
  void
  Simulator<dim>::compute_internal_force()
  {
    // f_int = sum over cells of t * int B^T sigma (thesis 3.25 with the
    // accumulated stress in place of the initial stress).
    // Computed from the stresses every step (not updated by K d and
    // turned with the spin), so that it is self-equilibrated in every
    // cell: turning nodal forces by nodal spins that differ from node to
    // node would leave a net force on a free, vibrating block.
    //
    // The strain energy is the state function sum t int sigma : S : sigma
    // / 2 (S = C^-1) less its initial value; unlike the accumulated work
    // d . f_int, it does not drift when stresses are turned with the spin.
    internal_force            = 0;
    const unsigned int n_dofs = fe->n_dofs_per_cell();
    const unsigned int n_q    = element_cache.n_quadrature_points();
    std::vector<SymmetricTensor<4, dim>> compliance;
    for (const auto &C : element_cache.get_elasticity())
      compliance.push_back(invert(C));
    double energy = 0;
    for (unsigned int c = 0; c < cell_dof_indices.size() / n_dofs; ++c)
      {
        const auto        &data     = element_cache[c];
        const auto        *dofs     = &cell_dof_indices[c * n_dofs];
        const unsigned int material = cell_material[c];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto &sigma = stress[c][q];
            for (unsigned int i = 0; i < n_dofs; ++i)
              internal_force[dofs[i]] +=
                (data.strain[q * n_dofs + i] * sigma) * data.weight[q];
            energy +=
              0.5 * (sigma * (compliance[material] * sigma)) * data.weight[q];
          }
      }
    if (!initial_strain_energy_known)
      {
        initial_strain_energy       = energy;
        initial_strain_energy_known = true;
      }
    stored_strain_energy = energy - initial_strain_energy;
    // Bolts pull their anchors towards each other with their spring force.
    for (const auto &bolt : bolts)
      {
        const Tensor<1, dim> l = bolt_geometry(bolt).second;
        for (unsigned int d = 0; d < dim; ++d)
          {
            internal_force[bolt.dofs[d]] += bolt.axial_force * l[d];
            internal_force[bolt.dofs[dim + d]] -= bolt.axial_force * l[d];
          }
      }
  }



  template <int dim>
  void
  Simulator<dim>::assemble_external_force(const double    t,
                                          Vector<double> &force) const
  {
    force.reinit(dof_handler.n_dofs());
    // Gravity, thesis 3.5.3 with consistent loads: f = M g.
    const Point<dim> origin;
    for (unsigned int d = 0; d < dim; ++d)
      {
        gravity->set_time(t);
        const double g = gravity->value(origin, d);
        if (g != 0.)
          force.add(g, gravity_load[d]);
      }
    // Point loads, thesis 3.5.1: f = N^T p at the material point.
    for (unsigned int l = 0; l < point_load_points.size(); ++l)
      {
        const auto &evaluator = point_load_points[l];
        point_load_functions[l]->set_time(t);
        const auto &p = parameters.loads.point_loads[l].point;
        for (unsigned int i = 0; i < evaluator.dofs.size(); ++i)
          force[evaluator.dofs[i]] +=
            evaluator.shape_values[i] *
            point_load_functions[l]->value(p, evaluator.component[i]);
      }
    // Line loads, thesis 3.5.2, integrated with the element's own shape
    // functions on the face.
    for (const auto &face : loaded_faces)
      {
        auto &function = *line_load_functions[face.line_load];
        function.set_time(t);
        const bool pressure =
          parameters.loads.line_loads[face.line_load].is_pressure;
        for (unsigned int q = 0; q < face.points.size(); ++q)
          {
            Tensor<1, dim> traction;
            if (pressure)
              traction = -function.value(face.points[q], 0) * face.normals[q];
            else
              for (unsigned int d = 0; d < dim; ++d)
                traction[d] = function.value(face.points[q], d);
            for (unsigned int i = 0; i < face.dofs.size(); ++i)
              force[face.dofs[i]] +=
                face.weighted_shape[q][i] * traction[face.component[i]];
          }
      }
    // Bolt pretension pulls the anchors together.
    for (const auto &bolt : bolts)
      if (bolt.pretension != 0.)
        {
          const Tensor<1, dim> l = bolt_geometry(bolt).second;
          for (unsigned int d = 0; d < dim; ++d)
            {
              force[bolt.dofs[d]] -= bolt.pretension * l[d];
              force[bolt.dofs[dim + d]] += bolt.pretension * l[d];
            }
        }
  }



  template <int dim>
  void
  Simulator<dim>::build_element_matrices(const bool only_moved_cells)
  {
    TimerOutput::Scope scope(timer, "element matrices");
    const double       tolerance = parameters.control.matrix_update_tolerance;
    // The first step uses the element matrices that setup() computed (it
    // needed them for the initial internal force); later steps recompute
    // those of the cells that moved.
    if (only_moved_cells)
      {
        const unsigned int n_computed =
          element_cache.update(dof_handler,
                               mapping,
                               parameters.materials,
                               tolerance > 0.,
                               tolerance);
        if (n_computed == 0)
          return;
      }
    ++n_matrix_rebuilds;
    assemble_global_matrices();
    // Gravity load vectors: M times a unit acceleration.
    for (unsigned int d = 0; d < dim; ++d)
      {
        Vector<double> unit(dof_handler.n_dofs());
        for (const auto &dofs : node_dofs)
          unit[dofs[d]] = 1.;
        mass_matrix.vmult(gravity_load[d], unit);
      }
    compute_internal_force();
    if (only_moved_cells)
      update_loaded_faces();
  }



  template <int dim>
  void
  Simulator<dim>::assemble_system_matrix(const double dt)
  {
    TimerOutput::Scope scope(timer, "system matrix");
    const auto        &control = parameters.control;
    double             c_mass  = 0.;
    if (control.analysis_type != parameters::AnalysisType::quasi_static)
      c_mass =
        (control.time_integrator == parameters::TimeIntegrator::dda ? 2. : 4.) /
        (dt * dt);
    system_matrix.copy_from(stiffness_matrix);
    if (c_mass != 0.)
      system_matrix.add(c_mass, mass_matrix);
    if (has_damping)
      system_matrix.add(1. / dt, damping_matrix);
    if (control.constraint_method == parameters::ConstraintMethod::penalty)
      for (const auto &nc : node_constraints)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              const double k =
                nc.type == parameters::ConstraintType::roller ?
                  penalty_stiffness * nc.normal[i] * nc.normal[j] :
                  (i == j ? penalty_stiffness : 0.);
              if (k != 0.)
                system_matrix.add(nc.dofs[i], nc.dofs[j], k);
            }
    assembled_dt     = dt;
    matrices_changed = false;
    base_factorized  = false;
  }



  template <int dim>
  void
  Simulator<dim>::factorize(const bool with_contacts)
  {
    // condensed_matrix holds the condensed system matrix, with the contact
    // springs already added if with_contacts.
    TimerOutput::Scope scope(timer, "factorize");
    linear_solver->factorize(condensed_matrix);
    base_factorized = !with_contacts;
  }



  template <int dim>
  void
  Simulator<dim>::compute_initial_acceleration()
  {
    // Newmark needs the acceleration at t = 0: M a0 = f_ext(0) - f_int, with
    // zero acceleration at constrained dofs.
    Vector<double> rhs;
    assemble_external_force(time, rhs);
    rhs -= internal_force;
    SparseMatrix<double> m(sparsity_pattern);
    m.copy_from(mass_matrix);
    if (parameters.control.constraint_method ==
        parameters::ConstraintMethod::penalty)
      for (const auto &nc : node_constraints)
        for (const auto dof : nc.dofs)
          {
            rhs[dof] = 0;
            for (auto entry = m.begin(dof); entry != m.end(dof); ++entry)
              entry->value() = (entry->column() == dof ? 1. : 0.);
          }
    constraints.condense(m);
    constraints.condense(rhs);
    // The consistent mass matrix is well conditioned (its condition number
    // does not grow with refinement): Jacobi-preconditioned CG needs a few
    // dozen iterations, far less than a factorization.
    Vector<double> acceleration(rhs.size());
    if (rhs.l2_norm() > 0)
      {
        SolverControl            control(1000, 1e-14 * rhs.l2_norm());
        SolverCG<Vector<double>> cg(control);
        PreconditionJacobi<SparseMatrix<double>> jacobi;
        jacobi.initialize(m);
        cg.solve(m, acceleration, rhs, jacobi);
      }
    constraints.distribute(acceleration);
    mass_matrix.vmult(inertia_force, acceleration);
  }



  template <int dim>
  void
  Simulator<dim>::prescribed_increment(const double    t0,
                                       const double    dt,
                                       Vector<double> &increment) const
  {
    // The increment that brings every constrained node to its prescribed
    // value at t0 + dt, measured from where it is now (so that no error
    // accumulates).
    increment = 0;
    for (const auto &nc : node_constraints)
      {
        Tensor<1, dim> current;
        for (unsigned int d = 0; d < dim; ++d)
          current[d] = displacement[nc.dofs[d]];
        const Point<dim> x0 = nc.position - current;
        Tensor<1, dim>   target_increment;
        switch (nc.type)
          {
            case parameters::ConstraintType::fixed:
              target_increment = -current;
              break;
            case parameters::ConstraintType::displacement:
              {
                auto &f = *constraint_functions[nc.function];
                f.set_time(t0 + dt);
                for (unsigned int d = 0; d < dim; ++d)
                  target_increment[d] = f.value(x0, d) - current[d];
                break;
              }
            case parameters::ConstraintType::velocity:
              {
                auto &f = *constraint_functions[nc.function];
                f.set_time(t0 + 0.5 * dt);
                for (unsigned int d = 0; d < dim; ++d)
                  target_increment[d] = f.value(x0, d) * dt;
                break;
              }
            case parameters::ConstraintType::roller:
              {
                auto &f = *constraint_functions[nc.function];
                f.set_time(t0 + dt);
                // Only the normal part is prescribed.
                target_increment =
                  (f.value(x0, 0) - nc.normal * current) * nc.normal;
                break;
              }
          }
        if (parameters.control.constraint_method ==
              parameters::ConstraintMethod::exact &&
            nc.type == parameters::ConstraintType::roller)
          {
            // Put the whole normal increment on the dependent component,
            // see setup_constraints().
            const unsigned int k =
              std::abs(nc.normal[1]) >= std::abs(nc.normal[0]) ? 1 : 0;
            increment[nc.dofs[k]] =
              (target_increment * nc.normal) / nc.normal[k];
          }
        else
          for (unsigned int d = 0; d < dim; ++d)
            increment[nc.dofs[d]] = target_increment[d];
      }
  }



  template <int dim>
  typename Simulator<dim>::StepResult
  Simulator<dim>::try_time_step(const double dt)
  {
    const auto &control = parameters.control;
    const bool  inertia =
      control.analysis_type != parameters::AnalysisType::quasi_static;
    const bool newmark =
      control.time_integrator == parameters::TimeIntegrator::newmark;
    const bool exact =
      control.constraint_method == parameters::ConstraintMethod::exact;
    const bool with_contact = parameters.contact.enabled;

    if (matrices_changed || dt != assembled_dt)
      assemble_system_matrix(dt);

    // Right-hand side at the end of the step (thesis 3.15):
    // f_ext(t1) - f_int + inertia terms of the integrator.
    Vector<double> rhs;
    {
      TimerOutput::Scope scope(timer, "solve");
      assemble_external_force(time + dt, step_external_force);
      rhs = step_external_force;
      rhs -= internal_force;
      if (inertia)
        {
          Vector<double> mv(velocity);
          mv *= (newmark ? 4. : 2.) / dt;
          mass_matrix.vmult_add(rhs, mv);
          if (newmark)
            rhs += inertia_force;
        }
    }

    Vector<double> prescribed(dof_handler.n_dofs());
    prescribed_increment(time, dt, prescribed);
    if (!exact)
      for (const auto &nc : node_constraints)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            rhs[nc.dofs[i]] += (nc.type == parameters::ConstraintType::roller ?
                                  nc.normal[i] * nc.normal[j] :
                                  (i == j ? 1. : 0.)) *
                               penalty_stiffness * prescribed[nc.dofs[j]];
    Vector<double> d(dof_handler.n_dofs());

    // The open-close iteration (thesis 2.3.13; DESIGN decision 5): solve
    // with the springs of the present contact states, classify the
    // contacts from the solution, and solve again until no state changes.
    // The element part of the matrix is kept; only contact springs change
    // between iterations.
    const unsigned int max_iterations =
      with_contact ? parameters.contact.max_open_close_iterations : 1;
    bool settled = false;
    for (unsigned int iteration = 0; iteration < max_iterations; ++iteration)
      {
        const bool     springs = with_contact && contacts.has_springs();
        Vector<double> b(rhs);
        // Newmark averages the forces at the step's start and end. A
        // contact that opens in this step would keep half of its start
        // force for the whole step and hand the body the energy
        // F0 g1 / 2 (g1 the gap it opens): only contacts closed at both
        // ends enter the average (doc/contact.md).
        inertia_correction.reinit(dof_handler.n_dofs());
        if (with_contact && newmark && inertia)
          {
            contacts.newmark_correction(inertia_correction);
            b += inertia_correction;
          }
        if (springs)
          {
            TimerOutput::Scope scope(timer, "contact assembly");
            condensed_matrix.copy_from(system_matrix);
            contacts.assemble(condensed_matrix, b);
          }
        else if (!base_factorized)
          condensed_matrix.copy_from(system_matrix);

        TimerOutput::Scope scope(timer, "solve");
        if (exact)
          {
            // d = d_h + d_g: d_g carries the prescribed values, d_h
            // satisfies the homogeneous constraints.
            if (!node_constraints.empty())
              {
                Vector<double> tmp(dof_handler.n_dofs());
                if (springs || !base_factorized)
                  condensed_matrix.vmult(tmp, prescribed);
                else
                  system_matrix.vmult(tmp, prescribed);
                b -= tmp;
              }
            constraints.condense(b);
          }
        if (springs || !base_factorized)
          {
            constraints.condense(condensed_matrix);
            // A changed system: try the last factorization as GMRES
            // preconditioner first (only contact springs or the contact
            // geometry differ), factorize if it does not serve.
            last_solver_iterations =
              with_contact && !refactorize_next ?
                linear_solver->solve_with_earlier_factorization(
                  condensed_matrix,
                  d,
                  b,
                  parameters.contact.reuse_iterations,
                  1e-12) :
                0;
            refactorize_next = false;
            if (last_solver_iterations == 0)
              {
                factorize(springs);
                last_solver_iterations = linear_solver->solve(d, b);
              }
            else if (2 * last_solver_iterations >
                     parameters.contact.reuse_iterations)
              // Converging slowly: the factorization has aged.
              refactorize_next = true;
          }
        else
          last_solver_iterations = linear_solver->solve(d, b);
        if (exact)
          {
            constraints.distribute(d);
            d += prescribed;
          }
        if (with_contact)
          contacts.count_iteration();
        if (!with_contact || !contacts.update_states(d))
          {
            settled = true;
            break;
          }
      }
    if (!settled)
      return StepResult::not_settled;

    // DDA step control: the largest nodal displacement must stay below the
    // allowed fraction of half the scene height.
    max_increment = 0;
    for (const auto &dofs : vertex_dofs)
      max_increment =
        std::max(max_increment,
                 d[dofs[0]] * d[dofs[0]] + d[dofs[1]] * d[dofs[1]]);
    max_increment = std::sqrt(max_increment);
    if (max_increment > control.max_displacement_ratio * scene_half_height)
      return StepResult::too_large;

    // A cell that the increment turns inside out: no strain measure of the
    // linear update holds there (its strain energy changes sign). Only a
    // diverging motion or a step far too large does this; cut the step.
    {
      const auto &block_mesh = mesh.get_block_mesh();
      for (const auto &t : block_mesh.triangles)
        {
          std::array<Point<dim>, 3> now, next;
          for (unsigned int k = 0; k < 3; ++k)
            {
              now[k] = next[k] = block_mesh.vertices[t[k]];
              for (unsigned int c = 0; c < dim; ++c)
                next[k][c] += d[vertex_dofs[t[k]][c]];
            }
          const auto twice_area = [](const std::array<Point<dim>, 3> &p) {
            return (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                   (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
          };
          if (twice_area(now) * twice_area(next) <= 0)
            return StepResult::inverted;
        }
    }

    if (with_contact &&
        parameters.contact.penalty_method ==
          parameters::PenaltyMethod::automatic &&
        contacts.max_penetration(d) > penetration_tolerance)
      {
        contacts.set_normal_stiffness(2. *
                                      contacts.get_settings().normal_stiffness);
        return StepResult::penalty_raised;
      }

    if (with_contact)
      contacts.end_step(d);
    update_state(d, dt);
    return StepResult::accepted;
  }



  template <int dim>
  void
  Simulator<dim>::update_state(const Vector<double> &d, const double dt)
  {
    TimerOutput::Scope scope(timer, "update");
    const auto        &control = parameters.control;

    // Velocity and acceleration at the end of the step. Both integrators
    // give v1 = 2 d / dt - v0; Newmark also carries the acceleration.
    if (control.analysis_type == parameters::AnalysisType::quasi_static)
      {
        velocity = d;
        velocity /= dt;
        inertia_force = 0;
      }
    else
      {
        if (control.time_integrator == parameters::TimeIntegrator::newmark)
          {
            // M a1 = 4 / dt^2 M (d - dt v0) - M a0, where M a0 leaves out
            // the start forces of contacts that opened in this step (see
            // try_time_step()).
            Vector<double> a(d), ma(d.size());
            a.add(-dt, velocity);
            a *= 4. / (dt * dt);
            mass_matrix.vmult(ma, a);
            ma -= inertia_force;
            ma -= inertia_correction;
            inertia_force = ma;
          }
        velocity *= -1.;
        velocity.add(2. / dt, d);
      }

    // Objective update: first turn the state of the step's start by the
    // increment's rotation, then add the increment's stress.
    if (control.rotate_with_spin)
      rotate_with_spin(d);

    // Stresses, per quadrature point: sigma += C eps(d).
    const unsigned int n_dofs = fe->n_dofs_per_cell();
    const unsigned int n_q    = element_cache.n_quadrature_points();
    const auto        &C      = element_cache.get_elasticity();
    for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
      {
        const unsigned int c    = cell->active_cell_index();
        const auto        &data = element_cache[c];
        const auto        *dofs = &cell_dof_indices[c * n_dofs];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            SymmetricTensor<2, dim> eps;
            for (unsigned int i = 0; i < n_dofs; ++i)
              eps += d[dofs[i]] * data.strain[q * n_dofs + i];
            stress[c][q] += C[cell->material_id()] * eps;
          }
      }

    if (control.analysis_type == parameters::AnalysisType::static_analysis)
      {
        // DDA statics: every step starts at rest (thesis 3.7).
        velocity      = 0;
        inertia_force = 0;
      }

    for (auto &bolt : bolts)
      {
        const Tensor<1, dim> l          = bolt_geometry(bolt).second;
        double               elongation = 0;
        for (unsigned int c = 0; c < dim; ++c)
          elongation += l[c] * (d[bolt.dofs[c]] - d[bolt.dofs[dim + c]]);
        bolt.axial_force += bolt.stiffness * elongation;
      }

    // Work of the loads over the step, by the trapezoidal rule.
    load_work += 0.5 * (external_force * d + step_external_force * d);
    external_force = step_external_force;

    // The internal force of the new stresses, and the strain energy they
    // hold.
    compute_internal_force();

    displacement += d;
    move_mesh(d);
    time += dt;
  }



  template <int dim>
  void
  Simulator<dim>::rotate_with_spin(const Vector<double> &d)
  {
    // The small-rotation update moves points along straight lines: a
    // spinning block would not turn its velocity. As DDA does with its
    // block rotation, turn the velocity (and inertia force) of each block
    // relative to its centre of mass by the block's rotation in the
    // increment, and each cell's stress by the cell's rotation
    // (Jaumann-like); the internal force follows from the turned stresses.
    // Only the part relative to the centre of mass turns: a block that
    // falls while it vibrates (its spin oscillating) keeps its momentum,
    // where turning whole nodal velocities by nodal spins made it drift
    // sideways by metres. See doc/theory.md.
    const unsigned int        n_dofs   = fe->n_dofs_per_cell();
    const unsigned int        n_q      = element_cache.n_quadrature_points();
    const unsigned int        n_blocks = mesh.n_blocks();
    std::vector<double>       block_spin(n_blocks), block_area(n_blocks);
    std::vector<unsigned int> node_block(node_dofs.size(),
                                         numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < cell_dof_indices.size() / n_dofs; ++c)
      {
        const auto &data  = element_cache[c];
        const auto *dofs  = &cell_dof_indices[c * n_dofs];
        double      omega = 0, area = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            for (unsigned int i = 0; i < n_dofs; ++i)
              omega += d[dofs[i]] * data.spin[q * n_dofs + i] * data.weight[q];
            area += data.weight[q];
          }
        const unsigned int b = mesh.block_of_cell(c);
        block_spin[b] += omega;
        block_area[b] += area;
        omega /= area;
        if (omega != 0.)
          {
            // sigma <- R sigma R^T
            const auto [cs, sn] = cos_sin(omega);
            for (auto &sigma : stress[c])
              {
                const double xx = sigma[0][0], yy = sigma[1][1],
                             xy = sigma[0][1];
                sigma[0][0] = cs * cs * xx - 2 * cs * sn * xy + sn * sn * yy;
                sigma[1][1] = sn * sn * xx + 2 * cs * sn * xy + cs * cs * yy;
                sigma[0][1] = cs * sn * (xx - yy) + (cs * cs - sn * sn) * xy;
              }
          }
        for (unsigned int i = 0; i < n_dofs; ++i)
          node_block[dof_to_node[dofs[i]]] = b;
      }

    // Centre-of-mass velocity and acceleration of each block, with the
    // row sums of the mass matrix as nodal masses (1^T M v is the momentum
    // for the consistent mass too).
    std::vector<double>         block_mass(n_blocks);
    std::vector<Tensor<1, dim>> block_velocity(n_blocks), block_force(n_blocks);
    std::vector<double>         node_mass(node_dofs.size());
    for (unsigned int n = 0; n < node_dofs.size(); ++n)
      {
        const unsigned int b = node_block[n];
        if (b == numbers::invalid_unsigned_int)
          continue;
        double m = 0;
        for (auto entry = mass_matrix.begin(node_dofs[n][0]);
             entry != mass_matrix.end(node_dofs[n][0]);
             ++entry)
          m += entry->value();
        node_mass[n] = m;
        block_mass[b] += m;
        for (unsigned int k = 0; k < dim; ++k)
          {
            block_velocity[b][k] += m * velocity[node_dofs[n][k]];
            block_force[b][k] += inertia_force[node_dofs[n][k]];
          }
      }
    for (unsigned int b = 0; b < n_blocks; ++b)
      if (block_mass[b] > 0.)
        {
          block_velocity[b] /= block_mass[b];
          block_force[b] /= block_mass[b]; // per unit mass
          block_spin[b] /= block_area[b];
        }

    for (unsigned int n = 0; n < node_dofs.size(); ++n)
      {
        const unsigned int b = node_block[n];
        if (b == numbers::invalid_unsigned_int || block_spin[b] == 0. ||
            block_mass[b] <= 0.)
          continue;
        const auto [cs, sn] = cos_sin(block_spin[b]);
        const auto [i, j]   = node_dofs[n];
        for (unsigned int k = 0; k < dim; ++k)
          {
            velocity[node_dofs[n][k]] -= block_velocity[b][k];
            inertia_force[node_dofs[n][k]] -= node_mass[n] * block_force[b][k];
          }
        rotate_pair(velocity, i, j, cs, sn);
        rotate_pair(inertia_force, i, j, cs, sn);
        for (unsigned int k = 0; k < dim; ++k)
          {
            velocity[node_dofs[n][k]] += block_velocity[b][k];
            inertia_force[node_dofs[n][k]] += node_mass[n] * block_force[b][k];
          }
      }
  }



  template <int dim>
  void
  Simulator<dim>::move_mesh(const Vector<double> &d)
  {
    std::vector<Tensor<1, dim>> vertex_increment(vertex_dofs.size());
    for (unsigned int v = 0; v < vertex_dofs.size(); ++v)
      for (unsigned int c = 0; c < dim; ++c)
        vertex_increment[v][c] = d[vertex_dofs[v][c]];
    mesh.move_vertices(vertex_increment);
  }



  template <int dim>
  void
  Simulator<dim>::setup_fracture()
  {
    fracture_edges.clear();
    fracture_strength.clear();
    const auto &materials = parameters.materials.materials;
    bool        any       = false;
    for (const auto &m : materials)
      any = any || m.fracture;
    fracture_enabled = any;
    if (!any)
      return;
    const auto &block_mesh = mesh.get_block_mesh();
    for (const auto &edge :
         fracture::find_interior_edges(block_mesh.triangles,
                                       block_mesh.vertices.size()))
      {
        if (mesh.is_cracked(edge.vertices[0], edge.vertices[1]))
          continue; // a closed crack (both tips inside a block)
        const auto &m0 = materials[cell_material[edge.cells[0]]];
        const auto &m1 = materials[cell_material[edge.cells[1]]];
        if (!m0.fracture || !m1.fracture)
          continue;
        fracture::Strength strength;
        strength.cohesion = std::min(m0.cohesion, m1.cohesion);
        strength.friction_angle =
          std::min(m0.friction_angle, m1.friction_angle) * numbers::PI / 180.;
        strength.tensile_strength =
          std::min(m0.tensile_strength, m1.tensile_strength);
        fracture_edges.push_back(edge);
        fracture_strength.push_back(strength);
      }
  }



  template <int dim>
  std::vector<SymmetricTensor<2, dim>>
  Simulator<dim>::cell_mean_stresses() const
  {
    std::vector<SymmetricTensor<2, dim>> mean(stress.size());
    for (unsigned int c = 0; c < stress.size(); ++c)
      mean[c] = mean_cell_stress(c);
    return mean;
  }



  template <int dim>
  std::vector<std::array<unsigned int, 2>>
  Simulator<dim>::check_fracture(
    const std::vector<Point<dim>>              &start_vertices,
    const std::vector<SymmetricTensor<2, dim>> &start_stresses,
    const double                                t0,
    const double                                dt)
  {
    static_assert(dim == 2, "fracture is two-dimensional");
    TimerOutput::Scope  scope(timer, "fracture check");
    const auto         &block_mesh = mesh.get_block_mesh();
    std::vector<double> area(stress.size());
    for (unsigned int c = 0; c < stress.size(); ++c)
      for (const double w : element_cache[c].weight)
        area[c] += w;
    const auto method = parameters.fracture.edge_stress_method;
    const auto start  = fracture::edge_states(fracture_edges,
                                             start_vertices,
                                             block_mesh.triangles,
                                             start_stresses,
                                             area,
                                             method);
    const auto end    = fracture::edge_states(fracture_edges,
                                           block_mesh.vertices,
                                           block_mesh.triangles,
                                           cell_mean_stresses(),
                                           area,
                                           method);
    const bool first_record_done =
      first_edge_failure.mode != fracture::FailureMode::none;
    n_failing_edges = 0;
    // The edges that fail, with their failure times (fractions of the
    // step); the earliest ones, within the crack window, crack first.
    std::vector<std::pair<double, unsigned int>> failing;
    for (unsigned int e = 0; e < fracture_edges.size(); ++e)
      {
        const fracture::EdgeFailure failure =
          parameters.fracture.criterion->failure_in_step(start[e],
                                                         end[e],
                                                         fracture_strength[e]);
        if (!failure.fails())
          continue;
        ++n_failing_edges;
        failing.emplace_back(failure.time, e);
        const double t = t0 + failure.time * dt;
        // The first check that finds failing edges keeps the earliest of
        // them; the re-solves after a crack do not change the record (a
        // crack can make another edge fail earlier within the same step).
        if (!first_record_done &&
            (first_edge_failure.mode == fracture::FailureMode::none ||
             t < first_edge_failure.time))
          {
            const auto &v               = fracture_edges[e].vertices;
            first_edge_failure.mode     = failure.mode;
            first_edge_failure.time     = t;
            first_edge_failure.location = Point<dim>(
              0.5 * (block_mesh.vertices[v[0]] + block_mesh.vertices[v[1]]));
          }
      }
    std::vector<std::array<unsigned int, 2>> edges;
    if (failing.empty())
      return edges;
    std::sort(failing.begin(), failing.end());
    const double last =
      failing.front().first + parameters.fracture.crack_window + 1e-12;
    for (const auto &[t, e] : failing)
      if (t <= last)
        edges.push_back(fracture_edges[e].vertices);
    return edges;
  }



  template <int dim>
  void
  Simulator<dim>::save_step_start(StepStart &start) const
  {
    start.displacement  = displacement;
    start.velocity      = velocity;
    start.inertia_force = inertia_force;
    start.stress        = stress;
    start.bolt_forces.clear();
    for (const auto &bolt : bolts)
      start.bolt_forces.push_back(bolt.axial_force);
    start.vertices  = mesh.get_block_mesh().vertices;
    start.contacts  = contacts;
    start.time      = time;
    start.load_work = load_work;
  }



  template <int dim>
  void
  Simulator<dim>::restore_step_start(const StepStart &start)
  {
    displacement  = start.displacement;
    velocity      = start.velocity;
    inertia_force = start.inertia_force;
    stress        = start.stress;
    for (unsigned int b = 0; b < bolts.size(); ++b)
      bolts[b].axial_force = start.bolt_forces[b];
    const auto                 &now = mesh.get_block_mesh().vertices;
    std::vector<Tensor<1, dim>> back(now.size());
    for (unsigned int v = 0; v < now.size(); ++v)
      back[v] = start.vertices[v] - now[v];
    mesh.move_vertices(back);
    contacts  = start.contacts;
    time      = start.time;
    load_work = start.load_work;
  }



  template <int dim>
  void
  Simulator<dim>::crack_edges(
    const std::vector<std::array<unsigned int, 2>> &edges)
  {
    TimerOutput::Scope scope(timer, "crack");
    // What the old dof numbering carries, before crack() empties the
    // DoFHandler: dof vectors by cell, the acceleration as M a over the
    // lumped mass (a force vector must not be copied to both sides of a
    // split node).
    const std::vector<types::global_dof_index> old_cell_dofs = cell_dof_indices;
    const auto                                 lumped_mass   = [this]() {
      Vector<double> m(mass_matrix.m());
      for (unsigned int i = 0; i < m.size(); ++i)
        for (auto entry = mass_matrix.begin(i); entry != mass_matrix.end(i);
             ++entry)
          m[i] += entry->value();
      return m;
    };
    const Vector<double> old_mass = lumped_mass();
    Vector<double>       acceleration(inertia_force);
    for (unsigned int i = 0; i < acceleration.size(); ++i)
      if (old_mass[i] > 0.)
        acceleration[i] /= old_mass[i];
    const Vector<double> old_displacement(displacement);
    const Vector<double> old_velocity(velocity);
    std::vector<double>  bolt_forces;
    for (const auto &bolt : bolts)
      bolt_forces.push_back(bolt.axial_force);
    const contact::ContactHandler old_contacts(contacts);

    mesh.crack(edges);
    n_cracked_edges += edges.size();

    setup_dofs(false);
    const auto transfer = [&](const Vector<double> &old, Vector<double> &now) {
      now.reinit(dof_handler.n_dofs());
      state_transfer::transfer_dof_values(old_cell_dofs,
                                          old,
                                          cell_dof_indices,
                                          now);
    };
    transfer(old_displacement, displacement);
    transfer(old_velocity, velocity);
    Vector<double> new_acceleration;
    transfer(acceleration, new_acceleration);
    // Constraints, loads and measure points are found by position on the
    // scene's initial geometry: set them up with the mesh moved back
    // there, then move it forward again.
    std::vector<Tensor<1, dim>> u(vertex_dofs.size());
    for (unsigned int v = 0; v < vertex_dofs.size(); ++v)
      for (unsigned int c = 0; c < dim; ++c)
        u[v][c] = -displacement[vertex_dofs[v][c]];
    mesh.move_vertices(u);
    setup_constraints();
    for (unsigned int b = 0; b < bolts.size(); ++b)
      bolts[b].axial_force = bolt_forces[b];
    setup_loads();
    measure_points.clear(); // their histories stay
    for (const auto &p : parameters.output.measure_points)
      measure_points.push_back(
        make_point_evaluator(p, "Output/Measure points"));
    for (auto &x : u)
      x *= -1.;
    mesh.move_vertices(u);

    setup_contacts();
    if (parameters.contact.enabled)
      contacts.carry_memory_from(old_contacts);
    setup_fracture();

    // A crack changes no cell's shape (cells keep their index, vertex
    // order and geometry; only dof numbers change): element matrices are
    // recomputed only for cells that moved beyond the tolerance since
    // their last computation, as in any step. Then global matrices,
    // gravity, internal force, loaded faces, and M a on the new mesh.
    const double tolerance = parameters.control.matrix_update_tolerance;
    element_cache.update(
      dof_handler, mapping, parameters.materials, tolerance > 0., tolerance);
    build_element_matrices(false);
    update_loaded_faces();
    inertia_force = lumped_mass();
    inertia_force.scale(new_acceleration);
    external_force.reinit(dof_handler.n_dofs());
    assemble_external_force(time, external_force);
    assembled_dt     = -1;
    base_factorized  = false;
    refactorize_next = false;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Simulator<dim>::mean_cell_stress(const unsigned int cell) const
  {
    const auto             &data = element_cache[cell];
    SymmetricTensor<2, dim> mean;
    double                  area = 0;
    for (unsigned int q = 0; q < stress[cell].size(); ++q)
      {
        mean += data.weight[q] * stress[cell][q];
        area += data.weight[q];
      }
    return mean / area;
  }



  template <int dim>
  double
  Simulator<dim>::kinetic_energy() const
  {
    return 0.5 * mass_matrix.matrix_norm_square(velocity);
  }



  template <int dim>
  void
  Simulator<dim>::record_measure_points()
  {
    for (unsigned int m = 0; m < measure_points.size(); ++m)
      {
        const auto   &e = measure_points[m];
        MeasureSample sample;
        sample.time = time;
        for (unsigned int i = 0; i < e.dofs.size(); ++i)
          {
            sample.displacement[e.component[i]] +=
              e.shape_values[i] * displacement[e.dofs[i]];
            sample.velocity[e.component[i]] +=
              e.shape_values[i] * velocity[e.dofs[i]];
          }
        sample.stress = mean_cell_stress(e.cell);
        measure_histories[m].push_back(sample);
      }
  }



  template <int dim>
  void
  Simulator<dim>::do_time_step()
  {
    if (!is_set_up)
      setup();
    Timer wall;
    if (step_number == 0)
      {
        build_element_matrices(false);
        if (parameters.control.analysis_type ==
              parameters::AnalysisType::dynamic_analysis &&
            parameters.control.time_integrator ==
              parameters::TimeIntegrator::newmark)
          compute_initial_acceleration();
        if (measure_histories.size() > 0 && measure_histories[0].empty())
          record_measure_points();
        time_step = parameters.control.time_step;
        assemble_external_force(time, external_force);
        initial_kinetic_energy = kinetic_energy();
      }
    else
      build_element_matrices(true);

    // The crack sequence (thesis 5.3): solve the step; if edges fail
    // within it, go back to the step's start, crack the earliest of them,
    // and solve the step again on the cracked mesh, until no edge fails
    // (or the limit on crack events is reached).
    const double t0      = time;
    const bool splitting = fracture_enabled && parameters.fracture.split_edges;
    StepStart  start;
    if (splitting)
      save_step_start(start);
    unsigned int crack_events    = 0;
    unsigned int cuts            = 0;
    unsigned int raises          = 0;
    unsigned int open_close_cuts = 0;
    crack_limit_hit              = false;
    double dt                    = 0;
    for (;;)
      {
        // Contacts are detected once per step, on the geometry of its start;
        // the detection distance covers every step size the cuts may try.
        if (parameters.contact.enabled)
          {
            {
              TimerOutput::Scope scope(timer, "contact detection");
              contacts.begin_step(mesh.get_block_mesh().vertices,
                                  contact_threshold);
            }
            update_sparsity_for_contacts();
          }

        // The last step ends exactly at the end time; a remainder within
        // round-off of the step size keeps the step size (and factorization).
        const double remaining = parameters.control.end_time - time;
        dt = remaining < time_step * (1. - 1e-9) ? remaining : time_step;
        // The fracture check compares the step's end with its start.
        std::vector<Point<dim>>              start_vertices;
        std::vector<SymmetricTensor<2, dim>> start_stresses;
        if (!fracture_edges.empty())
          {
            start_vertices = mesh.get_block_mesh().vertices;
            start_stresses = cell_mean_stresses();
          }
        StepResult result = StepResult::accepted;
        while ((result = try_time_step(dt)) != StepResult::accepted)
          {
            if (parameters.contact.enabled)
              contacts.restart_step();
            if (result == StepResult::penalty_raised)
              {
                ++raises;
                AssertThrow(raises <= 30,
                            ExcMessage(
                              "Step " + std::to_string(step_number + 1) +
                              " at t = " + Utilities::to_string(time) +
                              ": the automatic penalty was doubled 30 "
                              "times and the penetration still exceeds "
                              "Contact/Maximum penetration ratio. "
                              "Increase the ratio or reduce the time "
                              "step."));
                continue;
              }
            ++cuts;
            if (result == StepResult::not_settled)
              ++open_close_cuts;
            AssertThrow(
              cuts <= parameters.control.max_step_cuts,
              ExcMessage(
                "Step " + std::to_string(step_number + 1) +
                " at t = " + Utilities::to_string(time) + ": " +
                (result == StepResult::not_settled ?
                   "the open-close iteration still changes contact states "
                   "after Contact/Open-close iterations = " +
                     std::to_string(
                       parameters.contact.max_open_close_iterations) +
                     " solves" :
                 result == StepResult::inverted ?
                   std::string("a cell still turns inside out (the motion "
                               "diverges or the step is far too large)") :
                   "the largest displacement increment " +
                     Utilities::to_string(max_increment) +
                     " m still exceeds Control/Maximum displacement ratio " +
                     Utilities::to_string(
                       parameters.control.max_displacement_ratio) +
                     " of half the scene height") +
                ", after " + std::to_string(cuts - 1) +
                " step cuts. Increase 'Maximum step cuts' or the limit named, "
                "or reduce the time step."));
            dt *= 0.5;
            // Steps that each need a cut shrink the step without bound when
            // the motion diverges: stop rather than crawl.
            AssertThrow(
              dt >= 1e-6 * parameters.control.time_step,
              ExcMessage("Step " + std::to_string(step_number + 1) +
                         " at t = " + Utilities::to_string(time) +
                         ": the step size fell below 1e-6 of Control/Time step "
                         "after cuts in step after step; the motion is "
                         "diverging (largest increment " +
                         Utilities::to_string(max_increment) +
                         " m). Look at the last output and the statistics "
                         "file; see doc/contact.md, 'Known limits'."));
          }
        if (!fracture_edges.empty())
          {
            const auto failing =
              check_fracture(start_vertices, start_stresses, t0, dt);
            if (splitting && !failing.empty())
              {
                if (crack_events < parameters.fracture.max_crack_events)
                  {
                    restore_step_start(start);
                    crack_edges(failing);
                    ++crack_events;
                    save_step_start(start);
                    continue;
                  }
                crack_limit_hit = true;
              }
          }
        break;
      }
    step_cuts += cuts;
    n_crack_events += crack_events;
    ++step_number;
    last_dt = dt;
    // After a cut, grow back towards the nominal step.
    time_step = std::min(2. * dt, parameters.control.time_step);
    record_measure_points();
    last_step_time = wall.wall_time();

    statistics.add_value("Time step number", step_number);
    statistics.add_value("Time (s)", time);
    statistics.add_value("Time step size (s)", dt);
    statistics.add_value("Step cuts", cuts);
    statistics.add_value("Solver iterations", last_solver_iterations);
    statistics.add_value("Matrix builds", n_matrix_rebuilds);
    statistics.add_value("Kinetic energy (J)", kinetic_energy());
    statistics.add_value("Strain energy (J)", strain_energy());
    statistics.add_value("Max increment (m)", max_increment);
    if (fracture_enabled && parameters.fracture.split_edges)
      {
        statistics.add_value("Crack events", n_crack_events);
        statistics.add_value("Cracked edges", n_cracked_edges);
        statistics.add_value("Crack limit hit", crack_limit_hit ? 1 : 0);
      }
    if (fracture_enabled)
      statistics.add_value("Failing edges", n_failing_edges);
    if (parameters.contact.enabled)
      {
        const auto &c = contacts.get_statistics();
        statistics.add_value("Open-close iterations", c.n_iterations);
        statistics.add_value("Open-close cuts", open_close_cuts);
        statistics.add_value("Contact candidates", c.n_contacts);
        statistics.add_value("Closed contacts", c.n_closed);
        statistics.add_value("Sliding contacts", c.n_sliding);
        statistics.add_value("Vertex springs", c.n_vertex_springs);
        statistics.add_value("Bonded contacts", c.n_bonded);
        statistics.add_value("Max penetration (m)", c.max_penetration);
        statistics.add_value("Contact energy (J)", c.spring_energy);
        statistics.add_value("Contact dissipation (J)", c.dissipation);
        statistics.add_value("Normal stiffness (N/m)",
                             contacts.get_settings().normal_stiffness);
      }
    statistics.add_value("Work of loads (J)", load_work);
    statistics.add_value("Energy gain (J)", energy_error());
    statistics.add_value("Wall time per step (s)", last_step_time);
    if (step_number == 1)
      {
        std::vector<std::string> columns = {"Time (s)",
                                            "Time step size (s)",
                                            "Max increment (m)",
                                            "Kinetic energy (J)",
                                            "Strain energy (J)",
                                            "Work of loads (J)",
                                            "Energy gain (J)"};
        if (parameters.contact.enabled)
          for (const auto *c : {"Max penetration (m)",
                                "Contact energy (J)",
                                "Contact dissipation (J)",
                                "Normal stiffness (N/m)"})
            columns.push_back(c);
        for (const auto &c : columns)
          {
            statistics.set_scientific(c, true);
            statistics.set_precision(c, 6);
          }
      }

    // Each step starts at twice the last step size, so a motion that needs
    // a cut in step after step can crawl on at a small step size without
    // ever falling below the limit above. Stop once 1000 steps in a row
    // were below 1e-3 of the nominal step (all of them together cover less
    // than one nominal step); the statistics of this step are written.
    n_crawling_steps =
      dt < 1e-3 * parameters.control.time_step ? n_crawling_steps + 1 : 0;
    AssertThrow(n_crawling_steps < 1000,
                ExcMessage(
                  "Step " + std::to_string(step_number) +
                  " at t = " + Utilities::to_string(time) +
                  ": 1000 steps in a row were cut below 1e-3 of "
                  "Control/Time step (the last one " +
                  Utilities::to_string(dt) +
                  " s); the run crawls. The motion is diverging or the "
                  "contacts chatter: look at the last output and the "
                  "statistics file; see doc/contact.md, 'Known limits'."));
  }



  template <int dim>
  double
  Simulator<dim>::energy_error() const
  {
    const double spring_energy =
      parameters.contact.enabled ? contacts.get_statistics().spring_energy : 0.;
    return kinetic_energy() + strain_energy() + spring_energy - load_work -
           initial_kinetic_energy;
  }



  template <int dim>
  void
  Simulator<dim>::output_results()
  {
    TimerOutput::Scope scope(timer, "output");
    const auto        &out_parameters = parameters.output;
    const unsigned int n_cells = mesh.get_triangulation().n_active_cells();
    Vector<double>     sxx(n_cells), syy(n_cells), sxy(n_cells), s1(n_cells),
      s2(n_cells), block(n_cells), material(n_cells);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        const auto         s = mean_cell_stress(c);
        sxx[c]               = s[0][0];
        syy[c]               = s[1][1];
        sxy[c]               = s[0][1];
        const double mean    = 0.5 * (s[0][0] + s[1][1]);
        const double r       = std::sqrt(
          0.25 * (s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) + s[0][1] * s[0][1]);
        s1[c]       = mean + r;
        s2[c]       = mean - r;
        block[c]    = mesh.block_of_cell(c);
        material[c] = cell->material_id();
      }
    // The number of each cell's sides that are crack faces (pre-existing
    // or new): the faces of a fresh crack touch, so without this field a
    // picture cannot tell them from an unbroken edge. A crack face is a
    // side of its cell with the same vertex order.
    Vector<double> crack_faces(n_cells);
    if (!mesh.get_block_mesh().crack_edges.empty())
      {
        const auto &block_mesh = mesh.get_block_mesh();
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> side_of;
        for (unsigned int c = 0; c < block_mesh.triangles.size(); ++c)
          for (unsigned int j = 0; j < 3; ++j)
            side_of[{block_mesh.triangles[c][j],
                     block_mesh.triangles[c][(j + 1) % 3]}] = c;
        for (const auto &e : block_mesh.crack_edges)
          {
            const auto side = side_of.find({e[0], e[1]});
            if (side != side_of.end() && side->second < n_cells)
              crack_faces[side->second] += 1.;
          }
      }
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_kind(dim,
                  DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector_kind);
    data_out.add_data_vector(velocity,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data,
                             vector_kind);
    data_out.add_data_vector(sxx, "stress_xx", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(syy, "stress_yy", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(sxy, "stress_xy", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(s1,
                             "principal_stress_1",
                             DataOut<dim>::type_cell_data);
    data_out.add_data_vector(s2,
                             "principal_stress_2",
                             DataOut<dim>::type_cell_data);
    data_out.add_data_vector(block, "block_id", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(material,
                             "material_id",
                             DataOut<dim>::type_cell_data);
    data_out.add_data_vector(crack_faces,
                             "crack_faces",
                             DataOut<dim>::type_cell_data);
    data_out.build_patches(mapping, n_output_subdivisions);
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);

    const std::string number = Utilities::int_to_string(output_number, 5);
    if (out_parameters.write_vtu)
      {
        const std::string name = "solution-" + number + ".vtu";
        std::ofstream     vtu(out_parameters.directory + name);
        data_out.write_vtu(vtu);
        pvd_records.emplace_back(time, name);
        std::ofstream pvd(out_parameters.directory + "solution.pvd");
        DataOutBase::write_pvd_record(pvd, pvd_records);
        // The crack faces as segments on the present geometry, for
        // pictures: the faces of a fresh crack touch, and a VTU file
        // cannot tell them from an unbroken edge.
        const auto &block_mesh = mesh.get_block_mesh();
        if (!block_mesh.crack_edges.empty())
          {
            std::ofstream cracks(out_parameters.directory + "cracks-" + number +
                                 ".txt");
            cracks << "# crack faces at t = " << time
                   << " s: x1 y1 x2 y2 (m), one face per line\n"
                   << std::setprecision(10);
            for (const auto &e : block_mesh.crack_edges)
              cracks << block_mesh.vertices[e[0]] << ' '
                     << block_mesh.vertices[e[1]] << '\n';
          }
      }
    if (out_parameters.write_hdf5)
      {
        const std::string          name = "solution-" + number + ".h5";
        DataOutBase::DataOutFilter filter(
          DataOutBase::DataOutFilterFlags(true, true));
        data_out.write_filtered_data(filter);
        data_out.write_hdf5_parallel(filter,
                                     out_parameters.directory + name,
                                     MPI_COMM_SELF);
        xdmf_entries.push_back(
          data_out.create_xdmf_entry(filter, name, time, MPI_COMM_SELF));
        data_out.write_xdmf_file(xdmf_entries,
                                 out_parameters.directory + "solution.xdmf",
                                 MPI_COMM_SELF);
      }
    ++output_number;
  }



  template <int dim>
  void
  Simulator<dim>::write_statistics() const
  {
    std::ofstream out(parameters.output.directory + "statistics");
    statistics.write_text(out,
                          TableHandler::table_with_separate_column_description);

    std::ofstream history(parameters.output.directory + "measure_points.txt");
    history << "# time";
    for (unsigned int m = 0; m < measure_points.size(); ++m)
      {
        const auto &p = parameters.output.measure_points[m];
        history << "  [point " << m << " at " << p[0] << " " << p[1]
                << ": u_x u_y v_x v_y sigma_xx sigma_yy sigma_xy]";
      }
    history << '\n' << std::setprecision(10);
    if (!measure_histories.empty())
      for (unsigned int s = 0; s < measure_histories[0].size(); ++s)
        {
          history << measure_histories[0][s].time;
          for (const auto &h : measure_histories)
            history << ' ' << h[s].displacement << ' ' << h[s].velocity << ' '
                    << h[s].stress[0][0] << ' ' << h[s].stress[1][1] << ' '
                    << h[s].stress[0][1];
          history << '\n';
        }
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    if (!is_set_up)
      setup();

    // Everything is checked: only now is anything written.
    const std::string &directory = parameters.output.directory;
    std::filesystem::create_directories(directory);
    log_file.open(directory + "log.txt");
    tee_buffer =
      std::make_unique<TeeBuffer>(std::cout.rdbuf(), log_file.rdbuf());
    console.rdbuf(tee_buffer.get());
    if (parameters_from_file)
      {
        std::ofstream used(directory + "parameters.prm");
        prm.print_parameters(used, ParameterHandler::PRM);
      }

    pcout << "ndda: scene '" << parameters.scene_name << "'\n"
          << "  blocks: " << mesh.n_blocks()
          << ", cells: " << mesh.get_triangulation().n_active_cells()
          << ", vertices: " << mesh.get_triangulation().n_vertices()
          << ", degrees of freedom: " << dof_handler.n_dofs() << " ("
          << fe->base_element(0).get_name() << ")\n"
          << "  constrained nodes: " << node_constraints.size()
          << ", output: " << directory << std::endl;

    Timer        wall;
    double       last_progress = 0;
    const double end_time      = parameters.control.end_time;
    const double interval      = parameters.output.interval;
    output_results();
    next_output_time = interval;
    while (time < end_time * (1. - 1e-12))
      {
        try
          {
            do_time_step();
          }
        catch (...)
          {
            // Keep the rows since the last progress line: they show how
            // the run went wrong.
            write_statistics();
            throw;
          }
        if (time >= next_output_time * (1. - 1e-12) ||
            time >= end_time * (1. - 1e-12))
          {
            output_results();
            if (interval > 0)
              while (next_output_time <= time * (1. + 1e-12))
                next_output_time += interval;
          }
        if (wall.wall_time() - last_progress >=
              parameters.output.progress_interval ||
            time >= end_time * (1. - 1e-12))
          {
            last_progress     = wall.wall_time();
            const double rate = time / std::max(wall.wall_time(), 1e-9);
            pcout << "  step " << std::setw(7) << step_number
                  << "  t = " << std::setw(12) << std::setprecision(6) << time
                  << " s  dt = " << std::setw(10) << last_dt << " s"
                  << "  cuts " << step_cuts << "  ETA " << std::setprecision(3)
                  << std::max(0., (end_time - time) / std::max(rate, 1e-300))
                  << " s" << std::endl;
            write_statistics();
          }
      }
    write_statistics();
    pcout << "  done: " << step_number << " steps, " << step_cuts
          << " step cuts, " << n_matrix_rebuilds << " matrix builds, "
          << linear_solver->n_factorizations() << " factorizations, "
          << wall.wall_time() << " s wall time" << std::endl;
    timer.print_summary();
    console.flush();
    console.rdbuf(std::cout.rdbuf());
  }



  template class Simulator<2>;
} // namespace ndda
