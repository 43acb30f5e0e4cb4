// SPDX-License-Identifier: GPL-3.0-or-later
//
// split_vertices_along_edges on small hand-made meshes. The meshes are
// structured grids of squares, each cut into two counter-clockwise
// triangles by its diagonal from lower left to upper right. What is
// checked, case by case:
//  - interior_edge: one edge whose two end vertices are interior. Both are
//    crack tips with one fan each: no new vertex, the edge becomes two crack
//    faces of the same body.
//  - interior_polyline: two collinear edges with interior end vertices: the
//    tips keep one vertex, the middle vertex is split in two.
//  - boundary_to_interior: one edge from a boundary vertex to an interior
//    vertex: the boundary vertex is split (its open fan is cut once), the
//    tip is not: one new vertex.
//  - diagonal: a square of two triangles cut along the diagonal, an edge
//    from boundary to boundary: two new vertices, two bodies.
//  - across: a polyline across a 4x4 grid from boundary to boundary: every
//    vertex on it is split, two bodies.
//  - crossing: two crossing polylines: the centre vertex is split into 4,
//    the four tips are not.
//  - repeated: splitting again along edges that are crack faces already
//    keeps them in crack_edges and adds nothing.
//  - the crossing again with the cells in reverse order: the same corners
//    for every cell (the split does not follow the cells' numbering); and
//    ndda::hilbert_order() on a grid of squares steps from neighbour to
//    neighbour.
// For every case: the area and the orientation of every triangle are kept,
// new vertices are copies of the vertex they come from, crack_edges holds
// both faces of every split edge, and a bad edge is refused.

#include <deal.II/base/exceptions.h>

#include <ndda/base/utilities.h>
#include <ndda/geometry/block_mesh.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "values.h"

using namespace ndda::geometry;

namespace
{
  /**
   * Grid of nx x ny unit squares, vertex (i, j) has the index j*(nx+1)+i.
   */
  BlockMesh
  grid(const unsigned int nx, const unsigned int ny)
  {
    BlockMesh mesh;
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        mesh.vertices.emplace_back(i, j);
    const auto v = [&](const unsigned int i, const unsigned int j) {
      return j * (nx + 1) + i;
    };
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          mesh.triangles.push_back({{v(i, j), v(i + 1, j), v(i + 1, j + 1)}});
          mesh.triangles.push_back({{v(i, j), v(i + 1, j + 1), v(i, j + 1)}});
        }
    mesh.cell_block.assign(mesh.triangles.size(), 0);
    mesh.cell_material.assign(mesh.triangles.size(), 0);
    mesh.block_names = {"grid"};
    return mesh;
  }


  double
  signed_area(const BlockMesh &mesh, const std::array<unsigned int, 3> &t)
  {
    const auto &a = mesh.vertices[t[0]];
    const auto &b = mesh.vertices[t[1]];
    const auto &c = mesh.vertices[t[2]];
    return 0.5 *
           ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
  }


  /**
   * Number of bodies: triangles connected through shared edges.
   */
  unsigned int
  n_bodies(const BlockMesh &mesh)
  {
    std::vector<unsigned int> parent(mesh.triangles.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](unsigned int i) {
      while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    std::vector<std::pair<std::pair<unsigned int, unsigned int>, unsigned int>>
      sides;
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      for (unsigned int j = 0; j < 3; ++j)
        {
          const unsigned int a = mesh.triangles[c][j];
          const unsigned int b = mesh.triangles[c][(j + 1) % 3];
          sides.push_back({{std::min(a, b), std::max(a, b)}, c});
        }
    std::sort(sides.begin(), sides.end());
    for (std::size_t i = 0; i + 1 < sides.size(); ++i)
      if (sides[i].first == sides[i + 1].first)
        parent[find(sides[i].second)] = find(sides[i + 1].second);
    std::set<unsigned int> roots;
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      roots.insert(find(c));
    return roots.size();
  }


  unsigned int n_failures = 0;

  void
  check(const bool condition, const std::string &what)
  {
    if (!condition)
      {
        std::cerr << "FAILED: " << what << std::endl;
        ++n_failures;
      }
  }


  /**
   * Split @p mesh along @p edges and check the invariants; print a line of
   * measured values. Returns the split mesh.
   */
  BlockMesh
  run(const std::string                              &name,
      BlockMesh                                       mesh,
      const std::vector<std::array<unsigned int, 2>> &edges,
      const unsigned int                              expected_new_vertices,
      const unsigned int                              expected_bodies,
      const unsigned int                              expected_crack_edges)
  {
    const BlockMesh before      = mesh;
    double          area_before = 0.;
    for (const auto &t : before.triangles)
      area_before += signed_area(before, t);

    const std::vector<unsigned int> origin =
      split_vertices_along_edges(mesh, edges);

    const unsigned int n_new = mesh.vertices.size() - before.vertices.size();
    double             area_after = 0.;
    bool               all_kept   = true;
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      {
        const double a = signed_area(mesh, mesh.triangles[c]);
        area_after += a;
        // Same orientation and same corners as before.
        all_kept = all_kept && a > 0. &&
                   std::abs(a - signed_area(before, before.triangles[c])) == 0.;
        for (unsigned int j = 0; j < 3; ++j)
          all_kept =
            all_kept && origin[mesh.triangles[c][j]] == before.triangles[c][j];
      }
    bool copies_ok = origin.size() == mesh.vertices.size();
    for (unsigned int v = 0; v < mesh.vertices.size() && copies_ok; ++v)
      copies_ok =
        (v < before.vertices.size() ? origin[v] == v : origin[v] < v) &&
        mesh.vertices[v].distance(mesh.vertices[origin[v]]) == 0.;
    // Every crack edge is a side of a triangle and lies on a split edge.
    bool cracks_ok = true;
    for (const auto &e : mesh.crack_edges)
      {
        const unsigned int a = origin[e[0]];
        const unsigned int b = origin[e[1]];
        cracks_ok =
          cracks_ok &&
          (std::find_if(edges.begin(),
                        edges.end(),
                        [&](const auto &s) {
                          return (s[0] == a && s[1] == b) ||
                                 (s[0] == b && s[1] == a);
                        }) != edges.end() ||
           std::find_if(before.crack_edges.begin(),
                        before.crack_edges.end(),
                        [&](const auto &s) {
                          return (origin[s[0]] == a && origin[s[1]] == b) ||
                                 (origin[s[0]] == b && origin[s[1]] == a);
                        }) != before.crack_edges.end());
      }

    const unsigned int bodies = n_bodies(mesh);
    std::cout << name << ": vertices " << before.vertices.size() << " -> "
              << mesh.vertices.size() << ", new " << n_new << ", crack edges "
              << mesh.crack_edges.size() << ", bodies " << bodies << ", area "
              << area_after << ", area change " << area_after - area_before
              << std::endl;
    const std::string key = "geometry_split." + name;
    ndda_tests::record(key + ".new_vertices", n_new);
    ndda_tests::record(key + ".bodies", bodies);
    ndda_tests::record(key + ".area_change", area_after - area_before);

    check(n_new == expected_new_vertices, name + ": number of new vertices");
    check(bodies == expected_bodies, name + ": number of bodies");
    check(mesh.crack_edges.size() == expected_crack_edges,
          name + ": number of crack edges");
    check(area_after == area_before, name + ": area kept");
    check(all_kept, name + ": triangles keep corners and orientation");
    check(copies_ok, name + ": vertex map and copied coordinates");
    check(cracks_ok, name + ": crack edges lie on split edges");
    return mesh;
  }
} // namespace



int
main()
{
  // Vertex (i, j) of a 4x4 grid has the index 5j+i.
  const auto v = [](const unsigned int i, const unsigned int j) {
    return 5 * j + i;
  };

  run("interior_edge", grid(4, 4), {{{v(1, 2), v(2, 2)}}}, 0, 1, 2);
  run("interior_polyline",
      grid(4, 4),
      {{{v(1, 2), v(2, 2)}}, {{v(2, 2), v(3, 2)}}},
      1,
      1,
      4);
  run("boundary_to_interior", grid(4, 4), {{{v(0, 2), v(1, 2)}}}, 1, 1, 2);
  {
    BlockMesh square = grid(1, 1);
    run("diagonal", square, {{{0, 3}}}, 2, 2, 2);
  }
  const BlockMesh across = run("across",
                               grid(4, 4),
                               {{{v(0, 2), v(1, 2)}},
                                {{v(1, 2), v(2, 2)}},
                                {{v(2, 2), v(3, 2)}},
                                {{v(3, 2), v(4, 2)}}},
                               5,
                               2,
                               8);
  run("crossing",
      grid(4, 4),
      {{{v(1, 2), v(2, 2)}},
       {{v(2, 2), v(3, 2)}},
       {{v(2, 1), v(2, 2)}},
       {{v(2, 2), v(2, 3)}}},
      3,
      1,
      8);

  // Splitting along crack faces that are split already adds no vertex,
  // and the old crack faces stay crack faces.
  {
    std::vector<std::array<unsigned int, 2>> again;
    for (const auto &e : across.crack_edges)
      again.push_back(e);
    run("repeated", across, again, 0, 2, 8);
    run("repeated_empty", across, {}, 0, 2, 8);
  }

  // The split does not depend on the order of the cells: the crossing
  // split again with the cells in reverse order gives every cell the same
  // corners (which fan keeps a vertex, and the numbers of the new ones, go
  // by an order of the plane). A contact's memory is kept by vertex
  // number, so the side of a crack that keeps a number must not follow the
  // mesh's numbering.
  {
    const std::vector<std::array<unsigned int, 2>> crossing = {
      {{v(1, 2), v(2, 2)}},
      {{v(2, 2), v(3, 2)}},
      {{v(2, 1), v(2, 2)}},
      {{v(2, 2), v(2, 3)}}};
    BlockMesh forward = grid(4, 4), reverse = grid(4, 4);
    std::reverse(reverse.triangles.begin(), reverse.triangles.end());
    split_vertices_along_edges(forward, crossing);
    split_vertices_along_edges(reverse, crossing);
    const unsigned int n      = forward.triangles.size();
    unsigned int       n_same = 0;
    for (unsigned int c = 0; c < n; ++c)
      n_same += forward.triangles[c] == reverse.triangles[n - 1 - c];
    std::cout << "cells in reverse order: " << n_same << " of " << n
              << " cells with the same corners" << std::endl;
    ndda_tests::record("geometry_split.reverse_order_same_cells", n_same);
    check(n_same == n && forward.vertices.size() == reverse.vertices.size(),
          "the split does not depend on the order of the cells");
  }

  // ndda::hilbert_order() on the centres of a 16 x 16 grid: every step
  // along the curve goes to a neighbouring square.
  {
    std::vector<dealii::Point<2>> centres;
    for (unsigned int j = 0; j < 16; ++j)
      for (unsigned int i = 0; i < 16; ++i)
        centres.emplace_back(15 - i + 0.5, j + 0.5);
    const std::vector<unsigned int> order = ndda::hilbert_order(centres);
    std::vector<unsigned int>       sorted(order);
    std::sort(sorted.begin(), sorted.end());
    bool is_permutation = sorted.size() == centres.size();
    for (unsigned int i = 0; i < sorted.size() && is_permutation; ++i)
      is_permutation = sorted[i] == i;
    unsigned int n_unit_steps = 0;
    for (unsigned int i = 0; i + 1 < order.size() && is_permutation; ++i)
      n_unit_steps +=
        std::abs(centres[order[i]].distance(centres[order[i + 1]]) - 1.) <
        1e-12;
    std::cout << "Hilbert order of 256 squares: " << n_unit_steps
              << " of 255 steps to a neighbour" << std::endl;
    ndda_tests::record("geometry_split.hilbert_unit_steps", n_unit_steps);
    check(is_permutation && n_unit_steps == 255,
          "the Hilbert order steps from square to neighbouring square");
  }

  // Bad input is refused with a message.
  unsigned int n_refused = 0;
  for (const std::array<unsigned int, 2> bad :
       {std::array<unsigned int, 2>{{v(0, 0), v(2, 2)}},
        std::array<unsigned int, 2>{{v(1, 1), v(1, 1)}},
        std::array<unsigned int, 2>{{v(1, 1), 1000}}})
    {
      BlockMesh mesh   = grid(4, 4);
      bool      thrown = false;
      try
        {
          split_vertices_along_edges(mesh, {bad});
        }
      catch (const dealii::ExceptionBase &e)
        {
          thrown = true;
          ++n_refused;
          std::cout << "refused (" << bad[0] << ", " << bad[1] << "): ";
          e.print_info(std::cout);
        }
      check(thrown, "bad edge refused");
    }
  ndda_tests::record("geometry_split.refused", n_refused);

  std::cout << (n_failures == 0 ? "OK" : "FAILED") << std::endl;
  return n_failures == 0 ? 0 : 1;
}
