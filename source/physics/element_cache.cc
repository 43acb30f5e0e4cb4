// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/parallel.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/fe/fe_values.h>

#include <ndda/physics/element_cache.h>

#include <algorithm>

namespace ndda
{
  namespace
  {
    /**
     * Whether the cell of vertices @p now (the triangulation's vertices
     * @p positions at the indices @p now) moved by more than @p distance
     * from @p then, measured relative to its centroid and turned back by
     * @p turned, the turn of its block's frame since then: a translation,
     * or a turn with the frame, does not change the element matrices.
     */
    bool
    moved_beyond(const unsigned int            *now,
                 const std::vector<Point<2>>   &positions,
                 const std::array<Point<2>, 3> &then,
                 const double                   distance,
                 const double                   turned)
    {
      const unsigned int n = then.size();
      Tensor<1, 2>       now_centre, then_centre;
      for (unsigned int v = 0; v < n; ++v)
        {
          now_centre += positions[now[v]];
          then_centre += then[v];
        }
      now_centre /= n;
      then_centre /= n;
      const double c      = turned == 0. ? 1. : std::cos(turned),
                   s      = turned == 0. ? 0. : std::sin(turned);
      const double square = distance * distance;
      for (unsigned int v = 0; v < n; ++v)
        {
          const Tensor<1, 2> r = positions[now[v]] - now_centre;
          const Tensor<1, 2> back({c * r[0] + s * r[1], -s * r[0] + c * r[1]});
          if ((back - (then[v] - then_centre)).norm_square() > square)
            return true;
        }
      return false;
    }



    /**
     * @p values <- Q^T K Q: the element matrix K (@p values, n x n row by
     * row, n the size of @p partner) of the global frame in the frame
     * of angle @p angle, Q turning the (x, y) dofs of each node;
     * @p partner is the local dof of the other component of the same node,
     * @p component the component of each local dof.
     */
    void
    turn_to_frame(double                          *values,
                  const std::vector<unsigned int> &partner,
                  const std::vector<unsigned int> &component,
                  const double                     angle)
    {
      const double       c = std::cos(angle), s = std::sin(angle);
      const unsigned int n = partner.size();
      const auto         K = [values, n](const unsigned int i,
                                 const unsigned int j) -> double         &{
        return values[std::size_t(i) * n + j];
      };
      // Rows (Q^T K), then columns (K Q), each on the x dof of a node and
      // its partner: [x; y] <- [c x + s y; -s x + c y].
      for (unsigned int i = 0; i < n; ++i)
        if (component[i] == 0)
          for (unsigned int j = 0; j < n; ++j)
            {
              const double x = K(i, j), y = K(partner[i], j);
              K(i, j)          = c * x + s * y;
              K(partner[i], j) = -s * x + c * y;
            }
      for (unsigned int j = 0; j < n; ++j)
        if (component[j] == 0)
          for (unsigned int i = 0; i < n; ++i)
            {
              const double x = K(i, j), y = K(i, partner[j]);
              K(i, j)          = c * x + s * y;
              K(i, partner[j]) = -s * x + c * y;
            }
    }



    /** The edge vectors p1 - p0 and p2 - p0 of a triangle as columns. */
    template <int dim>
    Tensor<2, dim>
    edge_matrix(const std::array<Point<dim>, dim + 1> &p)
    {
      Tensor<2, dim> e;
      for (unsigned int k = 0; k < dim; ++k)
        for (unsigned int j = 0; j < dim; ++j)
          e[k][j] = p[j + 1][k] - p[0][k];
      return e;
    }



    /**
     * For each local dof of the vector element @p fe, the local dof of the
     * other component at the same node, and its component.
     */
    template <int dim>
    std::pair<std::vector<unsigned int>, std::vector<unsigned int>>
    node_pairs(const FiniteElement<dim> &fe)
    {
      const unsigned int        n = fe.n_dofs_per_cell();
      std::vector<unsigned int> partner(n), component(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          component[i] = fe.system_to_component_index(i).first;
          for (unsigned int j = 0; j < n; ++j)
            if (j != i && fe.system_to_component_index(j).second ==
                            fe.system_to_component_index(i).second)
              partner[i] = j;
        }
      return {partner, component};
    }



    /** The geometry the data of @p cell are computed on, into @p g. */
    template <typename CellIterator, typename CellGeometry>
    void
    record_geometry(const CellIterator &cell, CellGeometry &g)
    {
      AssertDimension(cell->n_vertices(), g.vertices.size());
      for (unsigned int v = 0; v < cell->n_vertices(); ++v)
        g.vertices[v] = cell->vertex(v);
      g.reference_inverse = invert(edge_matrix(g.vertices));
      g.diameter          = cell->diameter();
    }



    /**
     * The density @p density0 scaled by initial_area / area, the area that
     * of @p values (the cell quadrature) and @p initial_area the cell's
     * first (set on the first call): the mass of a cell never changes.
     */
    template <int dim>
    double
    conserved_density(const FEValues<dim> &values,
                      const double         density0,
                      double              &initial_area)
    {
      double area = 0;
      for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
        area += values.JxW(q);
      if (initial_area == 0)
        initial_area = area;
      return density0 * initial_area / area;
    }



    /**
     * Set @p mass (n x n values row by row, n the element's nodes) to the
     * scalar mass rho t int phi_a phi_b of nodes a and b (mass quadrature
     * in @p values; ElementCache::CellMass), @p node_dofs the local dof of
     * each node in the first component. The entry of dofs i and j of one
     * component is the same sum of the same products as the vector form
     * rho t int N_i . N_j gives it, whose other component is zero.
     */
    template <int dim>
    void
    add_mass_matrix(const FEValues<dim>             &values,
                    const double                     density_times_thickness,
                    const std::vector<unsigned int> &node_dofs,
                    double                          *mass)
    {
      const FEValuesExtractors::Vector u(0);
      const unsigned int               n_nodes = node_dofs.size();
      std::fill_n(mass, n_nodes * n_nodes, 0.);
      for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            const Tensor<1, dim> phi_a = values[u].value(node_dofs[a], q);
            for (unsigned int b = 0; b < n_nodes; ++b)
              mass[a * n_nodes + b] +=
                density_times_thickness * values.JxW(q) *
                (phi_a * values[u].value(node_dofs[b], q));
          }
    }


    /** The constitutive law of @p materials (linear elasticity if the
     * materials were built without the parameter file). */
    std::shared_ptr<const ConstitutiveLaw>
    law_of(const parameters::Materials &materials)
    {
      if (materials.constitutive_law != nullptr)
        return materials.constitutive_law;
      return ConstitutiveLawRegistry::create("linear elasticity");
    }


    /**
     * The gradient of the scalar shape function of every node and t JxW at
     * the points of @p values (the cell quadrature), into @p gradient and
     * @p weight (the cell's entries of the flat arrays; @p component and
     * @p node those of each local dof, ElementCache::dof_components() and
     * dof_nodes()), and the stiffness t int B^T C B into @p stiffness
     * (n x n values row by row, n the element's dofs), @p vector_gradient
     * a scratch array of a gradient per local dof.
     */
    template <int dim>
    void
    add_operators(const FEValues<dim>                        &values,
                  const std::vector<SymmetricTensor<4, dim>> &C,
                  const double                                t,
                  const std::vector<unsigned int>            &component,
                  const std::vector<unsigned int>            &node,
                  double                                     *stiffness,
                  std::vector<Tensor<2, dim>>                &vector_gradient,
                  Tensor<1, dim>                             *gradient,
                  double                                     *weight)
    {
      const FEValuesExtractors::Vector u(0);
      const unsigned int n_dofs = values.get_fe().n_dofs_per_cell();
      const unsigned int n_nodes =
        values.get_fe().base_element(0).n_dofs_per_cell();
      std::fill_n(stiffness, n_dofs * n_dofs, 0.);
      vector_gradient.resize(n_dofs);
      for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
        {
          weight[q] = t * values.JxW(q);
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              vector_gradient[i] = values[u].gradient(i, q);
              gradient[q * n_nodes + node[i]] =
                vector_gradient[i][component[i]];
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const SymmetricTensor<2, dim> Ceps_i =
                C[q] * symmetrize(vector_gradient[i]);
              for (unsigned int j = 0; j < n_dofs; ++j)
                stiffness[i * n_dofs + j] +=
                  (Ceps_i * symmetrize(vector_gradient[j])) * weight[q];
            }
        }
    }
  } // namespace



  template <int dim>
  void
  ElementCache<dim>::set_quadratures(const Quadrature<dim> &cell_quadrature,
                                     const Quadrature<dim> &mass_quadrature)
  {
    quadrature            = cell_quadrature;
    this->mass_quadrature = mass_quadrature;
  }



  template <int dim>
  void
  ElementCache<dim>::carry_to_cells(const refinement::RefineResult &refined)
  {
    if (geometry.size() != refined.n_old_cells)
      return; // nothing computed yet: update() computes every cell
    const unsigned int  n_cells  = refined.cell_origin.size();
    const std::size_t   n_matrix = stiffness_offset(1);
    const std::size_t   n_mass   = mass_offset(1);
    std::vector<double> carried_stiffness(n_cells * n_matrix),
      carried_mass(n_cells * n_mass), carried_viscosity(n_cells, 0.),
      carried_area(n_cells, 0.);
    // The parts of bisected cells start with no geometry (diameter 0):
    // update() computes them.
    std::vector<CellGeometry>   carried_geometry(n_cells);
    const unsigned int          n_gradients = n_q_points * nodes_per_cell;
    std::vector<Tensor<1, dim>> carried_gradients(std::size_t(n_cells) *
                                                  n_gradients);
    std::vector<double> carried_weights(std::size_t(n_cells) * n_q_points);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        // A cell not bisected is its own origin, which has no parts.
        if (!refined.is_part[c])
          {
            std::copy_n(stiffness_values.begin() + stiffness_offset(c),
                        n_matrix,
                        carried_stiffness.begin() + stiffness_offset(c));
            std::copy_n(mass_values.begin() + mass_offset(c),
                        n_mass,
                        carried_mass.begin() + mass_offset(c));
            carried_viscosity[c] = viscosity_over_density[c];
            carried_area[c]      = initial_area[c];
            carried_geometry[c]  = geometry[c];
            std::copy_n(gradients.begin() + std::size_t(c) * n_gradients,
                        n_gradients,
                        carried_gradients.begin() +
                          std::size_t(c) * n_gradients);
            std::copy_n(weights.begin() + std::size_t(c) * n_q_points,
                        n_q_points,
                        carried_weights.begin() + std::size_t(c) * n_q_points);
            continue;
          }
        const auto &r = refined.reference_vertices[c];
        // The part's share of the old cell: its area on the reference
        // triangle, whose area is 1/2.
        const double share =
          std::abs((r[1][0] - r[0][0]) * (r[2][1] - r[0][1]) -
                   (r[1][1] - r[0][1]) * (r[2][0] - r[0][0]));
        carried_area[c] = initial_area[refined.cell_origin[c]] * share;
      }
    stiffness_values.swap(carried_stiffness);
    mass_values.swap(carried_mass);
    viscosity_over_density.swap(carried_viscosity);
    initial_area.swap(carried_area);
    geometry.swap(carried_geometry);
    gradients.swap(carried_gradients);
    weights.swap(carried_weights);
  }



  template <int dim>
  void
  ElementCache<dim>::resize(const unsigned int n_cells)
  {
    stiffness_values.assign(stiffness_offset(n_cells), 0.);
    mass_values.assign(mass_offset(n_cells), 0.);
    viscosity_over_density.assign(n_cells, 0.);
    initial_area.assign(n_cells, 0.);
    geometry.assign(n_cells, CellGeometry());
    gradients.assign(std::size_t(n_cells) * n_q_points * nodes_per_cell,
                     Tensor<1, dim>());
    weights.assign(std::size_t(n_cells) * n_q_points, 0.);
  }



  template <int dim>
  std::vector<typename DoFHandler<dim>::active_cell_iterator>
  ElementCache<dim>::select_cells(const DoFHandler<dim>     &dof_handler,
                                  const DofMap              &dof_map,
                                  const bool                 only_moved_cells,
                                  const double               tolerance,
                                  const std::vector<double> *frame_angles)
  {
    computed_cells.clear();
    const auto &positions = dof_handler.get_triangulation().get_vertices();
    // The test of every cell on deal.II's threads, each into its own
    // flag; the list in cell order.
    const unsigned int n_cells = geometry.size();
    std::vector<char>  compute(n_cells, 1);
    if (only_moved_cells)
      parallel::apply_to_subranges(
        0u,
        n_cells,
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int c = begin; c < end; ++c)
            {
              const CellGeometry &g = geometry[c];
              compute[c] =
                g.diameter == 0. ||
                moved_beyond(dof_map.vertices_of_cell(c),
                             positions,
                             g.vertices,
                             tolerance * g.diameter,
                             (frame_angles != nullptr ? (*frame_angles)[c] :
                                                        0.) -
                               g.frame_angle);
            }
        },
        2048);
    for (unsigned int c = 0; c < n_cells; ++c)
      if (compute[c])
        computed_cells.push_back(c);
    std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;
    cells.reserve(computed_cells.size());
    auto next = computed_cells.begin();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (next == computed_cells.end())
          break;
        if (cell->active_cell_index() == *next)
          {
            cells.push_back(cell);
            ++next;
          }
      }
    return cells;
  }



  template <int dim>
  unsigned int
  ElementCache<dim>::update(
    const DoFHandler<dim>                      &dof_handler,
    const DofMap                               &dof_map,
    const Mapping<dim>                         &mapping,
    const parameters::Materials                &materials,
    const bool                                  only_moved_cells,
    const double                                tolerance,
    const std::vector<SymmetricTensor<2, dim>> *stresses,
    const std::vector<double>                  *frame_angles)
  {
    const auto &fe = dof_handler.get_fe();
    AssertThrow(quadrature.size() > 0 && mass_quadrature.size() > 0,
                ExcMessage("ElementCache::update(): call set_quadratures() "
                           "with the element's quadratures first."));
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    if (geometry.size() != n_cells || n_q_points != quadrature.size() ||
        dofs_per_cell != fe.n_dofs_per_cell())
      {
        // The vector element is dim copies of one scalar element
        // (Element): a local dof is a component of a node.
        AssertThrow(fe.n_base_elements() == 1 &&
                      fe.element_multiplicity(0) == dim && fe.is_primitive(),
                    ExcMessage("ElementCache: the finite element " +
                               fe.get_name() +
                               " is not dim copies of one scalar element."));
        n_q_points     = quadrature.size();
        dofs_per_cell  = fe.n_dofs_per_cell();
        nodes_per_cell = fe.base_element(0).n_dofs_per_cell();
        dof_component.resize(dofs_per_cell);
        dof_node.resize(dofs_per_cell);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            dof_component[i] = fe.system_to_component_index(i).first;
            dof_node[i]      = fe.system_to_component_index(i).second;
          }
        resize(n_cells);
      }
    law = law_of(materials);
    // A tangent that depends on the stress changes wherever the stress
    // does: every cell is computed, with the tangent at each point.
    const bool point_tangents =
      law->tangent_depends_on_stress() && stresses != nullptr;
    // The cells to compute, first: in most steps none has moved, and the
    // FEValues below cost more than the check.
    auto cells = select_cells(dof_handler,
                              dof_map,
                              only_moved_cells && !point_tangents,
                              tolerance,
                              frame_angles);
    if (computed_cells.empty())
      return 0;
    // On several processes each computes the cells it owns (the same
    // list on every process: the test above sees the same geometry).
    const bool split = owned_cells != nullptr && owned_cells->is_split();
    if (split)
      {
        owned_cells->check_size(n_cells, "ElementCache::update()");
        const auto not_owned = [this](const auto &cell) {
          const unsigned int c = cell->active_cell_index();
          return c < owned_cells->begin() || c >= owned_cells->end();
        };
        cells.erase(std::remove_if(cells.begin(), cells.end(), not_owned),
                    cells.end());
      }

    tangents.clear();
    for (const auto &material : materials.materials)
      tangents.push_back(law->tangent(material, materials.plane_strain));
    // Before the initial state is set the stresses are not sized yet.
    const bool stresses_known =
      point_tangents && stresses->size() == std::size_t(n_cells) * n_q_points;
    const auto node_pair = node_pairs(fe);
    // The local dof of each node in the first component (CellMass).
    std::vector<unsigned int> node_dofs(nodes_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      if (dof_component[i] == 0)
        node_dofs[dof_node[i]] = i;
    const double t = materials.thickness;

    // Every cell on deal.II's threads (WorkStream), each thread with
    // FEValues of its own; a cell writes only its own entries, so the data
    // do not depend on the number of threads (LinearMapping computes every
    // cell afresh).
    struct Scratch
    {
      Scratch(const Mapping<dim>       &mapping,
              const FiniteElement<dim> &fe,
              const Quadrature<dim>    &quadrature,
              const Quadrature<dim>    &mass_quadrature)
        : fe_values(mapping,
                    fe,
                    quadrature,
                    update_gradients | update_JxW_values)
        , mass_values(mapping,
                      fe,
                      mass_quadrature,
                      update_values | update_JxW_values)
        , C(quadrature.size())
      {}
      Scratch(const Scratch &other)
        : Scratch(other.fe_values.get_mapping(),
                  other.fe_values.get_fe(),
                  other.fe_values.get_quadrature(),
                  other.mass_values.get_quadrature())
      {}
      FEValues<dim>                        fe_values;
      FEValues<dim>                        mass_values;
      std::vector<SymmetricTensor<4, dim>> C;
      std::vector<Tensor<2, dim>>          vector_gradient;
    };
    struct NoCopy
    {};
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    const auto compute =
      [&](const typename std::vector<CellIterator>::const_iterator &position,
          Scratch                                                  &scratch,
          NoCopy &) {
        const CellIterator &cell   = *position;
        const unsigned int  c      = cell->active_cell_index();
        const std::size_t   offset = stiffness_offset(c);
        const double        frame_angle =
          frame_angles != nullptr ? (*frame_angles)[c] : 0.;
        scratch.fe_values.reinit(cell);
        scratch.mass_values.reinit(cell);
        const auto &material = materials.materials[cell->material_id()];
        for (unsigned int q = 0; q < n_q_points; ++q)
          scratch.C[q] =
            stresses_known ?
              law->point_tangent(material,
                                 materials.plane_strain,
                                 (*stresses)[std::size_t(c) * n_q_points + q]) :
              tangents[cell->material_id()];

        viscosity_over_density[c] =
          material.density > 0 ? material.viscosity / material.density : 0.;
        const double density = conserved_density(scratch.fe_values,
                                                 material.density,
                                                 initial_area[c]);

        add_operators(scratch.fe_values,
                      scratch.C,
                      t,
                      dof_component,
                      dof_node,
                      stiffness_values.data() + offset,
                      scratch.vector_gradient,
                      gradients.data() +
                        std::size_t(c) * n_q_points * nodes_per_cell,
                      weights.data() + std::size_t(c) * n_q_points);
        if (frame_angle != 0.)
          turn_to_frame(stiffness_values.data() + offset,
                        node_pair.first,
                        node_pair.second,
                        frame_angle);
        add_mass_matrix(scratch.mass_values,
                        density * t,
                        node_dofs,
                        mass_values.data() + mass_offset(c));
        record_geometry(cell, geometry[c]);
        geometry[c].frame_angle = frame_angle;
      };
    WorkStream::run(cells.cbegin(),
                    cells.cend(),
                    compute,
                    std::function<void(const NoCopy &)>(),
                    Scratch(mapping, fe, quadrature, mass_quadrature),
                    NoCopy());
    if (split)
      {
        owned_cells->share(stiffness_values,
                           dofs_per_cell * dofs_per_cell,
                           computed_cells);
        owned_cells->share(mass_values,
                           nodes_per_cell * nodes_per_cell,
                           computed_cells);
        owned_cells->share(viscosity_over_density, 1, computed_cells);
        owned_cells->share(initial_area, 1, computed_cells);
        owned_cells->share(geometry, 1, computed_cells);
        owned_cells->share(gradients,
                           n_q_points * nodes_per_cell,
                           computed_cells);
        owned_cells->share(weights, n_q_points, computed_cells);
      }
    return computed_cells.size();
  }



  template <int dim>
  bool
  ElementCache<dim>::tangent_depends_on_stress(
    const parameters::Materials &materials)
  {
    return law_of(materials)->tangent_depends_on_stress();
  }



  template class ElementCache<2>;
} // namespace ndda
