// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_loads_h
#define ndda_physics_loads_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/base/expression.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/physics_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  using dealii::Point;
  using dealii::Tensor;
  using dealii::Vector;

  /**
   * A fixed material point of the mesh: the dofs of its cell and the value
   * of each of the cell's shape functions there, so that a dof vector's
   * value at the point is a short sum.
   *
   * @ingroup physics
   */
  struct PointEvaluator
  {
    unsigned int                                 cell;
    std::vector<dealii::types::global_dof_index> dofs;
    /// Value of each local shape function; its component in component[i].
    std::vector<double>       shape_values;
    std::vector<unsigned int> component;

    /** The vector field @p v at the point. */
    Tensor<1, 2>
    value(const Vector<double> &v) const;
  };

  /**
   * Locate @p p in @p mesh and evaluate the shape functions of @p fe there;
   * throws an ExcMessage naming @p entry if the point lies outside every
   * block.
   */
  PointEvaluator
  make_point_evaluator(const CrackableMesh            &mesh,
                       const dealii::FiniteElement<2> &fe,
                       const DofMap                   &dof_map,
                       const Point<2>                 &p,
                       const std::string              &entry);

  /**
   * The external loads of a scene (thesis 3.5): gravity as the consistent
   * nodal forces M g, point loads N^T p at their material points, and
   * pressures and tractions on boundary segments integrated with the
   * element's own shape functions on the loaded faces of the present
   * geometry. Histories are muparser functions of x, y and t.
   *
   * @ingroup physics
   */
  class ExternalLoads
  {
  public:
    /**
     * Set up for a mesh and its dofs: the loaded faces of every line load
     * (throws naming the load if a segment touches no boundary edge) and
     * the material point of every point load. Call update() before
     * assemble().
     */
    void
    setup(const parameters::Loads     &loads,
          const CrackableMesh         &mesh,
          const dealii::DoFHandler<2> &dof_handler,
          const DofMap                &dof_map);

    /**
     * Recompute what depends on the geometry: the quadrature data of the
     * loaded faces with @p face_quadrature and @p thickness on the present
     * geometry.
     */
    void
    update_faces(const dealii::DoFHandler<2> &dof_handler,
                 const dealii::Mapping<2>    &mapping,
                 const dealii::Quadrature<1> &face_quadrature,
                 const double                 thickness);

    /** The gravity load vectors M e_x and M e_y, from the mass matrix. */
    void
    update_gravity(const dealii::SparseMatrix<double> &mass,
                   const DofMap                       &dof_map);

    /**
     * Evaluate every load's expression, every component, where the run
     * evaluates it (gravity at the origin, a point load at its point, a
     * line load at its faces' quadrature points) at each of @p times:
     * throws naming the entry on the first value that is not finite.
     * Call after update_faces().
     */
    void
    check_expressions(const std::vector<double> &times);

    /** Add the loads at time @p t to @p force. */
    void
    add(const double t, Vector<double> &force) const;

  private:
    /** Precomputed quadrature data of one loaded boundary face. */
    struct LoadedFace
    {
      unsigned int                                 line_load;
      unsigned int                                 cell;
      unsigned int                                 face;
      std::vector<dealii::types::global_dof_index> dofs;
      std::vector<unsigned int>                    component;
      /// shape_values[q][i] * JxW[q] * thickness
      std::vector<std::vector<double>> weighted_shape;
      std::vector<Point<2>>            points;
      std::vector<Tensor<1, 2>>        normals;
    };

    parameters::Loads                        loads;
    std::unique_ptr<Expression>              gravity;
    Vector<double>                           gravity_load[2];
    std::vector<std::unique_ptr<Expression>> point_functions;
    std::vector<PointEvaluator>              point_evaluators;
    std::vector<std::unique_ptr<Expression>> line_functions;
    std::vector<LoadedFace>                  loaded_faces;
  };
} // namespace ndda

#endif
