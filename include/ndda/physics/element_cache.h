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

#include <ndda/physics/constitutive_law.h>
#include <ndda/physics/physics_parameters.h>

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
   *   scene's constitutive law (Materials::constitutive_law),
   * - mass: rho t * int N^T N (consistent mass, thesis 3.60 without the
   *   time-step factor), with rho scaled to keep the cell's initial mass,
   * - at every point of the element's cell quadrature (QGaussSimplex(p),
   *   one point for P1, whose strain is constant; the stress lives at these
   *   points), the strain and the spin of each shape function and
   *   t * JxW, so that stress updates, internal forces and local rotations
   *   need no FEValues in the time loop. The mass matrix uses the mass
   *   quadrature, QGaussSimplex(p + 1). Both come with the element
   *   (physics/finite_element.h) through set_quadratures().
   *
   * @ingroup physics
   */
  template <int dim>
  class ElementCache
  {
  public:
    struct CellData
    {
      FullMatrix<double> stiffness;
      FullMatrix<double> mass;
      /// Viscosity over density: the damping matrix is this times mass.
      double viscosity_over_density = 0;
      /// strain[q * n_dofs + i]: symmetric gradient of shape function i.
      std::vector<SymmetricTensor<2, dim>> strain;
      /// spin[q * n_dofs + i]: (d phi_y / dx - d phi_x / dy) / 2.
      std::vector<double> spin;
      /// thickness * JxW at each quadrature point.
      std::vector<double> weight;
      /// Vertex positions when the data were computed.
      std::vector<Point<dim>> vertices;
      double                  diameter = 0;
      /// Area at the first computation: the density is scaled by
      /// initial_area / area so that the mass of a cell never changes.
      double initial_area = 0;
    };

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
     * (Re)compute the data of all cells, or with @p only_moved_cells only of
     * those whose vertices moved by more than @p tolerance times the cell
     * diameter since their last computation. Returns the number of cells
     * computed. If the constitutive law's tangent depends on the stress
     * and @p stresses (the stresses at every quadrature point, cell by
     * cell) are given, the stiffness uses the law's tangent at each point
     * and every cell is computed.
     */
    unsigned int
    update(const DoFHandler<dim>       &dof_handler,
           const Mapping<dim>          &mapping,
           const parameters::Materials &materials,
           const bool                   only_moved_cells,
           const double                 tolerance,
           const std::vector<std::vector<SymmetricTensor<2, dim>>> *stresses =
             nullptr);

    /** Whether the constitutive law of @p materials has a tangent that
     * depends on the stress. */
    static bool
    tangent_depends_on_stress(const parameters::Materials &materials);

    const CellData &
    operator[](const unsigned int cell) const
    {
      return data[cell];
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

    /** The cells whose data the last call to update() computed. */
    const std::vector<unsigned int> &
    get_computed_cells() const
    {
      return computed_cells;
    }

  private:
    std::vector<CellData>                  data;
    std::shared_ptr<const ConstitutiveLaw> law;
    std::vector<SymmetricTensor<4, dim>>   tangents;
    std::vector<unsigned int>              computed_cells;
    Quadrature<dim>                        quadrature;
    Quadrature<dim>                        mass_quadrature;
    unsigned int                           n_q_points = 0;
  };
} // namespace ndda

#endif
