// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small block meshes and fields for the unit tests of the mesh classes.

#ifndef ndda_tests_grids_h
#define ndda_tests_grids_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

#include <ndda/geometry/block_mesh.h>
#include <ndda/mesh/crackable_mesh.h>

namespace ndda_tests
{
  /**
   * An n x n grid of unit squares, each cut by its diagonal from lower
   * left to upper right, as one block of material 0, moved by
   * (@p x0, @p y0) and given block index @p block.
   */
  inline ndda::geometry::BlockMesh
  unit_grid(const unsigned int n,
            const double       x0    = 0,
            const double       y0    = 0,
            const unsigned int block = 0)
  {
    ndda::geometry::BlockMesh mesh;
    mesh.block_names = {"grid"};
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        mesh.vertices.emplace_back(x0 + i, y0 + j);
    const auto v = [&](const unsigned int i, const unsigned int j) {
      return j * (n + 1) + i;
    };
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          mesh.triangles.push_back({{v(i, j), v(i + 1, j), v(i + 1, j + 1)}});
          mesh.triangles.push_back({{v(i, j), v(i + 1, j + 1), v(i, j + 1)}});
        }
    mesh.cell_block.assign(mesh.triangles.size(), block);
    mesh.cell_material.assign(mesh.triangles.size(), 0);
    return mesh;
  }

  /** The vertex of @p mesh at @p p (present geometry), or invalid. */
  inline unsigned int
  vertex_at(const ndda::CrackableMesh &mesh, const dealii::Point<2> &p)
  {
    const auto &x = mesh.get_block_mesh().vertices;
    for (unsigned int v = 0; v < x.size(); ++v)
      if (x[v].distance(p) < 1e-12)
        return v;
    return dealii::numbers::invalid_unsigned_int;
  }

  /**
   * A field of two components that the element of degree @p degree (1 or
   * 2) holds exactly: linear, or quadratic.
   */
  class Field : public dealii::Function<2>
  {
  public:
    Field(const unsigned int degree)
      : dealii::Function<2>(2)
      , degree(degree)
    {}

    double
    value(const dealii::Point<2> &p,
          const unsigned int      component) const override
    {
      const double x = p[0], y = p[1];
      if (component == 0)
        return 1 + 2 * x - y + (degree == 2 ? x * x + 2 * x * y : 0.);
      return 3 * y - x + (degree == 2 ? y * y - 0.5 * x * y : 0.);
    }

  private:
    const unsigned int degree;
  };
} // namespace ndda_tests

#endif
