// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_element_cache_h
#define ndda_physics_element_cache_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/lac/full_matrix.h>

#include <ndda/mesh/refinement.h>
#include <ndda/parallel/owned_cells.h>
#include <ndda/physics/constitutive_law.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/physics_parameters.h>

#include <array>
#include <vector>

namespace ndda
{
  using namespace dealii;

  /**
   * Element matrices and operators of every cell, computed on the geometry
   * of the moment they were built and kept until the cell has moved too
   * much (DESIGN.md decision 4). For each cell:
   *
   * - stiffness: t * int B^T C B (thesis 3.24), C the tangent of the
   *   scene's constitutive law (Materials::constitutive_law), turned into
   *   the frame of the cell's block (BlockFrames) at the time: Q^T K Q,
   * - mass: rho t * int N^T N (consistent mass, thesis 3.60 without the
   *   time-step factor), with rho scaled to keep the cell's initial mass,
   *   kept as the scalar mass of the nodes (CellMass),
   * - at every point of the element's cell quadrature (QGaussSimplex(p),
   *   one point for P1, whose strain is constant; the stress lives at these
   *   points), the gradient of the scalar shape function of each node and
   *   t * JxW, so that stress updates and internal forces need no FEValues
   *   in the time loop (gradients_of(), weights_of()). The vector shape
   *   function of local dof i is that of node dof_nodes()[i] in component
   *   dof_components()[i]: a node's two dofs share one gradient, a quarter
   *   of the memory a gradient tensor per dof would stream,
   * - the cell's vertices and the inverse of its edge matrix
   *   [X1 - X0, X2 - X0] at the moment of computation (CellGeometry), so
   *   that the deformation gradient F = dx/dX of the cell's (affine)
   *   motion since then is two present edge vectors times it
   *   (deformation_gradient()): stresses and internal forces are exact on
   *   the present geometry however far the cell has turned since its data
   *   were computed (doc/theory.md).
   *
   * Every kind of datum is one flat array over the cells: the matrices
   * (read through operator[]), the
   * geometry and the operators, so that a pass over all cells streams
   * through memory (doc/performance.md, "ndda's own work in a steady
   * step") and a cell costs no bookkeeping of its own (its two matrices
   * as FullMatrix objects cost about 540 bytes a P1 cell beyond their
   * values, doc/performance.md "The element cache in flat arrays"). The
   * mass matrix uses the mass quadrature, QGaussSimplex(p + 1). Both come
   * with the element (physics/finite_element.h) through set_quadratures().
   *
   * @ingroup physics
   */
  template <int dim>
  class ElementCache
  {
  public:
    /**
     * A cell's element matrix in the cache: dofs_per_cell x dofs_per_cell
     * values, row by row, read in place.
     */
    class CellMatrix
    {
    public:
      CellMatrix(const double *values, const unsigned int size)
        : values(values)
        , size(size)
      {}

      const double &
      operator()(const unsigned int i, const unsigned int j) const
      {
        return values[std::size_t(i) * size + j];
      }

      unsigned int
      m() const
      {
        return size;
      }

      unsigned int
      n() const
      {
        return size;
      }

    private:
      const double *values;
      unsigned int  size;
    };

    /**
     * A cell's consistent mass in the cache. rho t int N^T N couples only
     * the dofs of one component, and those by the same scalar mass
     * rho t int phi_a phi_b of their nodes a and b in every component, so
     * the cache keeps that scalar matrix (nodes_per_cell^2 values, row by
     * row) and this view reads it as the dofs_per_cell x dofs_per_cell
     * matrix: a quarter of the values for a 2D element
     * (doc/performance.md, "The element mass by nodes").
     */
    class CellMass
    {
    public:
      CellMass(const double       *values,
               const unsigned int *component,
               const unsigned int *node,
               const unsigned int  n_dofs,
               const unsigned int  n_nodes)
        : values(values)
        , component(component)
        , node(node)
        , n_dofs(n_dofs)
        , n_nodes(n_nodes)
      {}

      double
      operator()(const unsigned int i, const unsigned int j) const
      {
        return component[i] == component[j] ?
                 values[std::size_t(node[i]) * n_nodes + node[j]] :
                 0.;
      }

      unsigned int
      m() const
      {
        return n_dofs;
      }

      unsigned int
      n() const
      {
        return n_dofs;
      }

    private:
      const double       *values;
      const unsigned int *component;
      const unsigned int *node;
      unsigned int        n_dofs;
      unsigned int        n_nodes;
    };

    /** What operator[] gives of a cell: views of its matrices and its two
     * numbers. */
    struct CellData
    {
      CellMatrix stiffness;
      CellMass   mass;
      /// Viscosity over density: the damping matrix is this times mass.
      double viscosity_over_density;
      /// Area at the first computation: the density is scaled by
      /// initial_area / area so that the mass of a cell never changes.
      double initial_area;
    };

    /**
     * The geometry a cell's data were computed on. The loops of every
     * step read it (the deformation gradient, the test for motion), so
     * it lives in one array of its own, apart from the matrices.
     */
    struct CellGeometry
    {
      /// Vertex positions when the data were computed.
      std::array<Point<dim>, dim + 1> vertices;
      /// Inverse of the edge matrix [X1 - X0, X2 - X0] (columns) of the
      /// vertices when the data were computed.
      Tensor<2, dim> reference_inverse;
      /// The angle of the block's frame when the data were computed.
      double frame_angle = 0;
      /// The cell's diameter then; 0: not computed yet.
      double diameter = 0;

      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &vertices &reference_inverse &frame_angle &diameter;
      }
    };

    /**
     * Write the cells' data to a checkpoint or read them (Archive): a cell
     * keeps the matrices of its last computation until it moves beyond
     * the tolerance, so they are state, not something to recompute.
     */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar &stiffness_values &mass_values &viscosity_over_density &initial_area
        &geometry &gradients &weights &dofs_per_cell &nodes_per_cell
          &dof_component &dof_node &tangents &computed_cells;
    }

    /**
     * After a refinement (CrackableMesh::refine()): cells not bisected keep
     * their data (their index too); the parts of a bisected cell start
     * empty, so the next update() computes them, with the mass of their
     * share of the old cell (initial_area scaled by the part's share of
     * the old cell's reference triangle), so that no mass is gained or
     * lost.
     */
    void
    carry_to_cells(const refinement::RefineResult &refined);

    /**
     * The quadratures of the element (Element::cell_quadrature and
     * Element::mass_quadrature); set them before the first update().
     *
     * @param cell_quadrature For stiffness, strain and stress.
     * @param mass_quadrature For the consistent mass.
     */
    void
    set_quadratures(const Quadrature<dim> &cell_quadrature,
                    const Quadrature<dim> &mass_quadrature);

    /**
     * Share the computation of the cells in update() among the processes
     * that @p owned_cells splits the cells among (referenced; it must
     * split as many cells as update() is given): each process computes
     * the cells it owns, and then every process has every cell's data.
     * nullptr (the default): this process computes every cell.
     */
    void
    set_owned_cells(const OwnedCells *owned_cells)
    {
      this->owned_cells = owned_cells;
    }

    /**
     * (Re)compute the data of all cells, or with @p only_moved_cells only of
     * those whose vertices moved by more than @p tolerance times the cell
     * diameter since their last computation, seen from the frame of the
     * cell's block (@p frame_angles, by cell; none: the global frame), so
     * that a cell that only turned with its block's frame has not moved.
     * Returns the number of cells computed. If the constitutive law's
     * tangent depends on the stress and @p stresses (the stresses at every
     * quadrature point: n_quadrature_points() of cell 0, then of cell 1,
     * and so on) are given, the stiffness uses the law's tangent at each
     * point and every cell is computed.
     */
    unsigned int
    update(const DoFHandler<dim>                      &dof_handler,
           const DofMap                               &dof_map,
           const Mapping<dim>                         &mapping,
           const parameters::Materials                &materials,
           const bool                                  only_moved_cells,
           const double                                tolerance,
           const std::vector<SymmetricTensor<2, dim>> *stresses     = nullptr,
           const std::vector<double>                  *frame_angles = nullptr);

    /** Whether the constitutive law of @p materials has a tangent that
     * depends on the stress. */
    static bool
    tangent_depends_on_stress(const parameters::Materials &materials);

    CellData
    operator[](const unsigned int cell) const
    {
      return {CellMatrix(stiffness_values.data() + stiffness_offset(cell),
                         dofs_per_cell),
              CellMass(mass_values.data() + mass_offset(cell),
                       dof_component.data(),
                       dof_node.data(),
                       dofs_per_cell,
                       nodes_per_cell),
              viscosity_over_density[cell],
              initial_area[cell]};
    }

    /**
     * The gradients d phi_n / dX of the scalar shape functions of the
     * nodes of cell @p cell at its quadrature points, on the geometry of
     * the computation: entry q * n_nodes_per_cell() + n for node n at
     * point q. The vector shape function of local dof i has the gradient
     * of node dof_nodes()[i] in row dof_components()[i], zero elsewhere.
     */
    const Tensor<1, dim> *
    gradients_of(const unsigned int cell) const
    {
      return gradients.data() + std::size_t(cell) * n_q_points * nodes_per_cell;
    }

    /** The number of nodes (scalar shape functions) of a cell. */
    unsigned int
    n_nodes_per_cell() const
    {
      return nodes_per_cell;
    }

    /** The vector component of each local dof. */
    const std::vector<unsigned int> &
    dof_components() const
    {
      return dof_component;
    }

    /** The node (scalar shape function) of each local dof. */
    const std::vector<unsigned int> &
    dof_nodes() const
    {
      return dof_node;
    }

    /**
     * The gradient dd/dX at point @p q of cell @p cell of the field whose
     * values at the cell's local dofs are @p values at @p dofs (the
     * cell's global dofs): the sum over local dofs i, in their order, of
     * values[dofs[i]] times the gradient of node dof_nodes()[i], into row
     * dof_components()[i].
     */
    template <typename VectorType>
    Tensor<2, dim>
    field_gradient(const unsigned int             cell,
                   const unsigned int             q,
                   const VectorType              &values,
                   const types::global_dof_index *dofs) const
    {
      const Tensor<1, dim> *g =
        gradients_of(cell) + std::size_t(q) * nodes_per_cell;
      Tensor<2, dim> gradient;
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const double value = values[dofs[i]];
          for (unsigned int k = 0; k < dim; ++k)
            gradient[dof_component[i]][k] += value * g[dof_node[i]][k];
        }
      return gradient;
    }

    /** Thickness times JxW at the quadrature points of cell @p cell. */
    const double *
    weights_of(const unsigned int cell) const
    {
      return weights.data() + std::size_t(cell) * n_q_points;
    }

    /**
     * The deformation gradient F = dx/dX of cell @p cell from the geometry
     * its data were computed on to the present one: @p vertices are the
     * triangulation's vertices, @p cell_vertices the indices of the cell's
     * (DofMap::vertices_of_cell()). The cell's motion is affine (straight
     * sides), so F is its present edge matrix times
     * CellGeometry::reference_inverse.
     */
    Tensor<2, dim>
    deformation_gradient(const unsigned int             cell,
                         const unsigned int            *cell_vertices,
                         const std::vector<Point<dim>> &vertices) const
    {
      std::array<Point<dim>, dim + 1> x;
      for (unsigned int v = 0; v <= dim; ++v)
        x[v] = vertices[cell_vertices[v]];
      return deformation_gradient(cell, x);
    }

    /** The deformation gradient of cell @p cell whose vertices are at
     * @p x (in the order of DofMap::vertices_of_cell()). */
    Tensor<2, dim>
    deformation_gradient(const unsigned int                     cell,
                         const std::array<Point<dim>, dim + 1> &x) const
    {
      Tensor<2, dim> edges;
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          edges[k][j] = x[j + 1][k] - x[0][k];
      return edges * geometry[cell].reference_inverse;
    }

    /** The constitutive law of the last update(). */
    const ConstitutiveLaw &
    get_constitutive_law() const
    {
      return *law;
    }

    /** The law's tangent of every material, by material id. */
    const std::vector<SymmetricTensor<4, dim>> &
    get_tangents() const
    {
      return tangents;
    }

    unsigned int
    n_quadrature_points() const
    {
      return n_q_points;
    }

    /** The cell quadrature: the stresses live at its points. */
    const Quadrature<dim> &
    get_quadrature() const
    {
      return quadrature;
    }

    /** The quadrature of the consistent mass. */
    const Quadrature<dim> &
    get_mass_quadrature() const
    {
      return mass_quadrature;
    }

    /** The cells whose data the last call to update() computed. */
    const std::vector<unsigned int> &
    get_computed_cells() const
    {
      return computed_cells;
    }

  private:
    /**
     * The cells update() computes: all, or with @p only_moved_cells those
     * that moved beyond @p tolerance; into computed_cells too. The test
     * reads plain arrays (@p dof_map's cell vertices, the triangulation's
     * vertices): it runs over every cell in every step.
     */
    std::vector<typename DoFHandler<dim>::active_cell_iterator>
    select_cells(const DoFHandler<dim>     &dof_handler,
                 const DofMap              &dof_map,
                 const bool                 only_moved_cells,
                 const double               tolerance,
                 const std::vector<double> *frame_angles);

    /** Size the arrays of the cells' data for @p n_cells cells, none
     * computed. */
    void
    resize(const unsigned int n_cells);

    /** Where the stiffness of cell @p cell starts in stiffness_values. */
    std::size_t
    stiffness_offset(const unsigned int cell) const
    {
      return std::size_t(cell) * dofs_per_cell * dofs_per_cell;
    }

    /** Where the scalar mass of cell @p cell starts in mass_values. */
    std::size_t
    mass_offset(const unsigned int cell) const
    {
      return std::size_t(cell) * nodes_per_cell * nodes_per_cell;
    }

    /// The cells' stiffness matrices, dofs_per_cell^2 values a cell, and
    /// their scalar masses, nodes_per_cell^2 values a cell (CellMass), row
    /// by row (operator[]).
    std::vector<double> stiffness_values, mass_values;
    /// By cell: CellData::viscosity_over_density and
    /// CellData::initial_area.
    std::vector<double>       viscosity_over_density, initial_area;
    std::vector<CellGeometry> geometry;
    /// The cells' scalar shape gradients and weights (gradients_of(),
    /// weights_of()).
    std::vector<Tensor<1, dim>>            gradients;
    std::vector<double>                    weights;
    unsigned int                           dofs_per_cell  = 0;
    unsigned int                           nodes_per_cell = 0;
    std::vector<unsigned int>              dof_component, dof_node;
    std::shared_ptr<const ConstitutiveLaw> law;
    std::vector<SymmetricTensor<4, dim>>   tangents;
    std::vector<unsigned int>              computed_cells;
    Quadrature<dim>                        quadrature;
    Quadrature<dim>                        mass_quadrature;
    unsigned int                           n_q_points  = 0;
    const OwnedCells                      *owned_cells = nullptr;
  };
} // namespace ndda

#endif
