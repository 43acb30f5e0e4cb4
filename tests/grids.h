// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small block meshes, their motion and fields for the unit tests of the mesh
// classes and of contact detection.

#ifndef ndda_tests_grids_h
#define ndda_tests_grids_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

#include <ndda/contact/contact_detection.h>
#include <ndda/geometry/block_mesh.h>
#include <ndda/mesh/crackable_mesh.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

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

  /**
   * @p n_blocks small blocks, triangles and squares by turns (sizes 0.02 to
   * 0.05, turned at random), their centres at random in [0, @p width] x
   * [0, 1]: @p random draws each block's centre, size and angle in turn.
   * With @p left_to_right the blocks, and so their cells, are numbered by
   * the x of their centres.
   */
  inline ndda::geometry::BlockMesh
  random_blocks(const unsigned int n_blocks,
                const double       width,
                std::mt19937      &random,
                const bool         left_to_right = false)
  {
    struct Block
    {
      dealii::Point<2> center;
      double           size, angle;
      unsigned int     corners;
    };
    std::uniform_real_distribution<double> unit(0., 1.);
    std::vector<Block>                     blocks(n_blocks);
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        const dealii::Point<2> center(width * unit(random), unit(random));
        const double           size  = 0.02 + 0.03 * unit(random);
        const double           angle = 2. * M_PI * unit(random);
        blocks[b] = {center, size, angle, (b % 2 == 0 ? 3u : 4u)};
      }
    if (left_to_right)
      std::stable_sort(blocks.begin(),
                       blocks.end(),
                       [](const Block &a, const Block &b) {
                         return a.center[0] < b.center[0];
                       });
    ndda::geometry::BlockMesh mesh;
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        const Block       &block = blocks[b];
        const unsigned int n     = mesh.vertices.size();
        for (unsigned int k = 0; k < block.corners; ++k)
          {
            const double phi = block.angle + 2. * M_PI * k / block.corners;
            mesh.vertices.emplace_back(block.center[0] +
                                         block.size * std::cos(phi),
                                       block.center[1] +
                                         block.size * std::sin(phi));
          }
        mesh.triangles.push_back({{n, n + 1, n + 2}});
        if (block.corners == 4)
          mesh.triangles.push_back({{n, n + 2, n + 3}});
        mesh.cell_block.insert(mesh.cell_block.end(), block.corners - 2, b);
        mesh.cell_material.insert(mesh.cell_material.end(),
                                  block.corners - 2,
                                  0);
        mesh.block_names.push_back("b" + std::to_string(b));
      }
    return mesh;
  }

  /**
   * Move every block of @p mesh by a random shift of up to @p scale along
   * each axis and a turn of up to 10 @p scale radians about its first
   * vertex (@p random draws the shift and the angle block after block).
   */
  inline void
  move_blocks(ndda::geometry::BlockMesh &mesh,
              std::mt19937              &random,
              const double               scale)
  {
    std::uniform_real_distribution<double> unit(-1., 1.);
    std::vector<std::vector<unsigned int>> nodes(mesh.block_names.size());
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      nodes[mesh.cell_block[c]].insert(nodes[mesh.cell_block[c]].end(),
                                       mesh.triangles[c].begin(),
                                       mesh.triangles[c].end());
    for (std::vector<unsigned int> &block : nodes)
      {
        std::sort(block.begin(), block.end());
        block.erase(std::unique(block.begin(), block.end()), block.end());
        const dealii::Tensor<1, 2> shift(
          {scale * unit(random), scale * unit(random)});
        const double           angle  = 10. * scale * unit(random);
        const dealii::Point<2> center = mesh.vertices[block[0]];
        for (const unsigned int v : block)
          {
            const dealii::Tensor<1, 2> r = mesh.vertices[v] - center;
            mesh.vertices[v] =
              center + shift +
              dealii::Tensor<1, 2>(
                {std::cos(angle) * r[0] - std::sin(angle) * r[1],
                 std::sin(angle) * r[0] + std::cos(angle) * r[1]});
          }
      }
  }

  /** True if @p a and @p b are the same candidates, field by field. */
  inline bool
  same_candidates(const std::vector<ndda::contact::Candidate> &a,
                  const std::vector<ndda::contact::Candidate> &b)
  {
    bool same = (a.size() == b.size());
    for (unsigned int k = 0; same && k < a.size(); ++k)
      same = a[k].vertex == b[k].vertex && a[k].edge == b[k].edge &&
             a[k].type == b[k].type && a[k].distance == b[k].distance &&
             a[k].edge_ratio == b[k].edge_ratio;
    return same;
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
