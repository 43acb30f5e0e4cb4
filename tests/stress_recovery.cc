// SPDX-License-Identifier: GPL-3.0-or-later
//
// StressRecovery (the 'nodal stress' VTU fields): the L2 projection of the
// stresses at the quadrature points onto the element's own space,
//  1. reproduces at every node a stress of the degree the element's
//     stresses have (constant for P1, linear for P2), on a mesh of two
//     squares that touch along x = 1 with separate nodes there (a crack
//     face or a block boundary), each with its own field: the projection
//     must not mix them;
//  2. for P1, the patch recovery (the default for linear elements)
//     reproduces a linear stress at every node, boundary nodes and the
//     pieces' corners included, while the L2 projection alone cannot (its
//     error falls with h);
//  3. for P2, a quadratic stress is not reproduced at the nodes (the
//     cell's three points cannot hold it), but the error falls as h^2.

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <ndda/postprocess/stress_recovery.h>

#include "tests.h"

using namespace dealii;
using namespace ndda_tests;
using Stress = SymmetricTensor<2, 2>;

namespace
{
  /**
   * The squares [0, 1]^2 and [1, 2] x [0, 1], n x n x 2 triangles each,
   * with separate vertices on x = 1.
   */
  void
  two_squares(Triangulation<2> &result, const unsigned int n)
  {
    std::vector<Point<2>>    vertices;
    std::vector<CellData<2>> cells;
    for (const double shift : {0., 1.})
      {
        Triangulation<2> square;
        GridGenerator::subdivided_hyper_rectangle_with_simplices(
          square, {n, n}, Point<2>(shift, 0), Point<2>(shift + 1, 1));
        const unsigned int offset = vertices.size();
        for (const auto &v : square.get_vertices())
          vertices.push_back(v);
        for (const auto &cell : square.active_cell_iterators())
          {
            CellData<2> c(3);
            for (unsigned int i = 0; i < 3; ++i)
              c.vertices[i] = offset + cell->vertex_index(i);
            cells.push_back(c);
          }
      }
    result.create_triangulation(vertices, cells, SubCellData());
  }

  /** The stress field of the piece x < 1 (left) or x > 1. */
  Stress
  field(const Point<2> &p, const bool left, const unsigned int degree)
  {
    Stress       s;
    const double x = p[0], y = p[1];
    if (degree == 0)
      {
        s[0][0] = left ? 3e6 : -2e6;
        s[1][1] = left ? -1e6 : 5e6;
        s[0][1] = left ? 0.5e6 : 7e6;
      }
    else if (degree == 1)
      {
        s[0][0] = left ? 1e6 + 2e6 * x - 3e6 * y : -4e6 + 1e6 * y;
        s[1][1] = left ? 2e6 * y : 3e6 - 5e6 * x + 2e6 * y;
        s[0][1] = left ? -1e6 + 0.5e6 * x : 6e6 * x - 1e6 * y;
      }
    else
      {
        s[0][0] = 1e6 * x * x - 2e6 * x * y;
        s[1][1] = 3e6 * y * y + 1e6 * x;
        s[0][1] = 2e6 * x * y;
      }
    return s;
  }

  /**
   * Recover the stress @p degree_of_field on the two squares (n x n) with
   * FE_SimplexP(@p degree); return the largest error at a node (Pa).
   */
  double
  recovery_error(
    const unsigned int                                    degree,
    const unsigned int                                    degree_of_field,
    const unsigned int                                    n,
    const ndda::postprocess::StressRecovery::LinearMethod method =
      ndda::postprocess::StressRecovery::LinearMethod::patch_recovery)
  {
    Triangulation<2> mesh;
    two_squares(mesh, n);
    const FESystem<2> fe(FE_SimplexP<2>(degree), 2);
    DoFHandler<2>     dofs(mesh);
    dofs.distribute_dofs(fe);
    const MappingFE<2>     mapping(FE_SimplexP<2>(1));
    const QGaussSimplex<2> cell_quadrature(degree);
    const QGaussSimplex<2> mass_quadrature(degree + 1);
    FEValues<2> values(mapping, fe, cell_quadrature, update_quadrature_points);
    std::vector<std::vector<Stress>> stresses(mesh.n_active_cells());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        values.reinit(cell);
        const bool left = cell->center()[0] < 1;
        for (const auto &p : values.get_quadrature_points())
          stresses[cell->active_cell_index()].push_back(
            field(p, left, degree_of_field));
      }

    ndda::postprocess::StressRecovery recovery(method);
    recovery.recover(dofs, mapping, cell_quadrature, mass_quadrature, stresses);
    check(recovery.n_projected_nodes() == 0,
          "every node recovered without falling back to the projection");
    const auto           &recovered = recovery.get_dof_handler();
    std::vector<Point<2>> support(recovered.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, recovered, support);
    double                               error = 0;
    std::vector<types::global_dof_index> local(
      recovered.get_fe().n_dofs_per_cell());
    for (const auto &cell : recovered.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        const bool left = cell->center()[0] < 1;
        for (const auto i : local)
          {
            const Stress d =
              recovery.at_dof(i) - field(support[i], left, degree_of_field);
            error = std::max(error, d.norm());
          }
      }
    return error;
  }
} // namespace



int
main()
{
  std::cout << std::setprecision(3);
  // 1. Exact for the element's own stresses, each piece its own field.
  for (const unsigned int degree : {1u, 2u})
    {
      const double error = recovery_error(degree, degree - 1, 4);
      std::cout << "P" << degree << ", a stress of degree " << degree - 1
                << " on two pieces: largest error at a node " << error << " Pa"
                << std::endl;
      // CG stops at 1e-13 of the right-hand side: 1e-9 of the 1e6 Pa
      // fields is round-off.
      check(error < 1e-3, "P" + std::to_string(degree) + " reproduces it");
    }
  // 2. P1 and a linear stress: the patch recovery reproduces it; the
  // projection of one constant a cell cannot (and no piece sees the
  // other's): its error is there, and falls with h.
  const double patch = recovery_error(1, 1, 4);
  std::cout << "P1, a linear stress, patch recovery: largest error at a node "
            << patch << " Pa" << std::endl;
  check(patch < 1e-3, "P1 patch recovery reproduces a linear stress");
  using Method           = ndda::postprocess::StressRecovery::LinearMethod;
  const double p1_coarse = recovery_error(1, 1, 4, Method::projection);
  const double p1_fine   = recovery_error(1, 1, 8, Method::projection);
  std::cout << "P1, a linear stress, projection: largest error " << p1_coarse
            << " Pa (h = 1/4), " << p1_fine << " Pa (h = 1/8)" << std::endl;
  check(p1_coarse > 1e3 && p1_fine < 0.6 * p1_coarse,
        "P1 projection: linear stress, an error that falls with h");

  // 3. P2 and a quadratic stress: the error falls as h^2.
  const double coarse = recovery_error(2, 2, 4);
  const double fine   = recovery_error(2, 2, 8);
  std::cout << "P2, a quadratic stress: largest error " << coarse
            << " Pa (h = 1/4), " << fine << " Pa (h = 1/8), ratio "
            << coarse / fine << std::endl;
  check(coarse > 1e3 && coarse / fine > 3.,
        "P2: quadratic stress, the error falls as h^2");
  std::cout << "OK" << std::endl;
}
