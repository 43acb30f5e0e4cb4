// SPDX-License-Identifier: GPL-3.0-or-later
//
// Block cutting and meshing with mesh_scene(). The scene:
//  - region "rock", the unit square, cut by a horizontal and a vertical
//    joint that both stick out of it (the outside parts are ignored), and a
//    dangling joint from (0.5, 0.25) on the vertical joint to (0.8, 0.25),
//    which ends inside the lower right block;
//  - region "slab", [0,1]x[2,3] with a hole [0.4,0.6]x[2.4,2.6], cut by a
//    vertical joint through the hole into two C-shaped (non-convex) blocks,
//    plus a free joint from (0.1, 2.8) to (0.3, 2.8) that touches nothing;
//  - block "ring", [2,3]x[0,1] with the hole [2.4,2.6]x[0.4,0.6], meshed
//    with a target number of cells;
//  - block "cracked", [4,5]x[0,1] with a crack from (4, 0.2) on its
//    boundary to the tip (4.5, 0.7) inside; it meets the boundary at 45
//    degrees.
// Checked: block names and count; per block the sum of the triangle areas
// against the exact area (relative 1e-12); all triangles counter-clockwise;
// every angle in [30 - 1e-6, 120 + 1e-6] degrees except for the triangles
// at (4, 0.2), the only input angle below 60 degrees (45 degrees, which the
// mesher cannot split into angles of at least 30 degrees); no vertex shared
// between blocks and every block's vertices are one contiguous range; crack
// edges lie exactly on the dangling joint and the crack, with the total
// length of both faces; vertices on them are split except at the tips
// inside; required vertices are mesh vertices; the same input gives the
// same mesh; with keep_dangling_as_cracks = false the dangling joints are
// gone and the explicit crack stays.

#include <deal.II/base/exceptions.h>

#include <ndda/geometry/block_mesh.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "values.h"

using namespace ndda::geometry;
using dealii::Point;

namespace
{
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


  std::vector<Point<2>>
  rectangle(const double x0, const double y0, const double x1, const double y1)
  {
    return {Point<2>(x0, y0),
            Point<2>(x1, y0),
            Point<2>(x1, y1),
            Point<2>(x0, y1)};
  }


  SceneGeometry
  make_scene(const bool keep_dangling)
  {
    SceneGeometry scene;

    BlockDescription ring;
    ring.name           = "ring";
    ring.outer          = rectangle(2, 0, 3, 1);
    ring.holes          = {rectangle(2.4, 0.4, 2.6, 0.6)};
    ring.material_id    = 1;
    ring.target_n_cells = 400;
    scene.blocks.push_back(ring);

    BlockDescription cracked;
    cracked.name        = "cracked";
    cracked.outer       = rectangle(4, 0, 5, 1);
    cracked.cracks      = {{Point<2>(4, 0.2), Point<2>(4.5, 0.7)}};
    cracked.material_id = 2;
    cracked.mesh_size   = 0.08;
    scene.blocks.push_back(cracked);

    RegionDescription rock;
    rock.name                    = "rock";
    rock.outer                   = rectangle(0, 0, 1, 1);
    rock.joints                  = {{Point<2>(-0.2, 0.5), Point<2>(1.2, 0.5)},
                                    {Point<2>(0.5, -0.2), Point<2>(0.5, 1.2)},
                                    {Point<2>(0.5, 0.25), Point<2>(0.8, 0.25)}};
    rock.keep_dangling_as_cracks = keep_dangling;
    rock.material_id             = 3;
    rock.mesh_size               = 0.1;
    scene.regions.push_back(rock);

    RegionDescription slab;
    slab.name                    = "slab";
    slab.outer                   = rectangle(0, 2, 1, 3);
    slab.holes                   = {rectangle(0.4, 2.4, 0.6, 2.6)};
    slab.joints                  = {{Point<2>(0.5, 1.9), Point<2>(0.5, 3.1)},
                                    {Point<2>(0.1, 2.8), Point<2>(0.3, 2.8)}};
    slab.keep_dangling_as_cracks = keep_dangling;
    slab.material_id             = 4;
    slab.mesh_size               = 0.1;
    scene.regions.push_back(slab);

    scene.required_vertices = {Point<2>(0.25, 0.25),
                               Point<2>(0.75, 0.5),
                               Point<2>(2.5, 0.),
                               Point<2>(10., 10.)};
    return scene;
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


  /** Angles of a triangle in degrees. */
  std::array<double, 3>
  angles(const BlockMesh &mesh, const std::array<unsigned int, 3> &t)
  {
    std::array<double, 3> result;
    for (unsigned int j = 0; j < 3; ++j)
      {
        const auto  &p = mesh.vertices[t[j]];
        const auto   u = mesh.vertices[t[(j + 1) % 3]] - p;
        const auto   w = mesh.vertices[t[(j + 2) % 3]] - p;
        const double c = u * w / (u.norm() * w.norm());
        result[j]      = std::acos(std::max(-1., std::min(1., c))) * 180. /
                    dealii::numbers::PI;
      }
    return result;
  }


  /** Whether p lies on the segment [a, b] up to @p tol. */
  bool
  on_segment(const Point<2> &p,
             const Point<2> &a,
             const Point<2> &b,
             const double    tol = 1e-12)
  {
    const auto   d = b - a;
    const double t = (p - a) * d / d.norm_square();
    return t >= -tol && t <= 1 + tol && (a + t * d).distance(p) <= tol;
  }


  /** Number of vertices of block @p b at the point p. */
  unsigned int
  copies_at(const BlockMesh &mesh, const unsigned int b, const Point<2> &p)
  {
    std::set<unsigned int> found;
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      if (mesh.cell_block[c] == b)
        for (const unsigned int v : mesh.triangles[c])
          if (mesh.vertices[v].distance(p) <= 1e-12)
            found.insert(v);
    return found.size();
  }


  unsigned int
  block_index(const BlockMesh &mesh, const std::string &name)
  {
    const auto it =
      std::find(mesh.block_names.begin(), mesh.block_names.end(), name);
    AssertThrow(it != mesh.block_names.end(),
                dealii::ExcMessage("no block named " + name));
    return it - mesh.block_names.begin();
  }


  /**
   * Check the crack edges of block @p name: all on @p segment, total length
   * 2 |segment| (both faces), interior points split in two, @p a split into
   * @p copies_a and @p b into @p copies_b vertices.
   */
  void
  check_crack(const BlockMesh   &mesh,
              const std::string &name,
              const Segment     &segment,
              const unsigned int copies_a,
              const unsigned int copies_b)
  {
    const unsigned int                  b      = block_index(mesh, name);
    double                              length = 0.;
    bool                                all_on = true;
    std::set<std::pair<double, double>> points;
    unsigned int                        n_edges = 0;
    for (const auto &e : mesh.crack_edges)
      {
        // Crack edges of this block: both vertices belong to it.
        bool in_block = false;
        for (unsigned int c = 0; c < mesh.triangles.size() && !in_block; ++c)
          if (mesh.cell_block[c] == b)
            in_block = std::count(mesh.triangles[c].begin(),
                                  mesh.triangles[c].end(),
                                  e[0]) > 0;
        if (!in_block)
          continue;
        ++n_edges;
        const Point<2> &p = mesh.vertices[e[0]];
        const Point<2> &q = mesh.vertices[e[1]];
        all_on            = all_on && on_segment(p, segment.a, segment.b) &&
                 on_segment(q, segment.a, segment.b);
        length += p.distance(q);
        points.insert({p[0], p[1]});
        points.insert({q[0], q[1]});
      }
    const double expected = 2. * segment.a.distance(segment.b);
    bool         split_ok = true;
    for (const auto &xy : points)
      {
        const Point<2>     p(xy.first, xy.second);
        const unsigned int n = copies_at(mesh, b, p);
        if (p.distance(segment.a) <= 1e-12)
          split_ok = split_ok && n == copies_a;
        else if (p.distance(segment.b) <= 1e-12)
          split_ok = split_ok && n == copies_b;
        else
          split_ok = split_ok && n == 2;
      }
    std::cout << "  crack in " << name << ": " << n_edges
              << " crack edges, length " << length << " (expected " << expected
              << "), " << points.size() << " distinct points" << std::endl;
    check(n_edges > 0, name + ": has crack edges");
    check(all_on, name + ": crack edges lie on the crack segment");
    check(std::abs(length - expected) <= 1e-12 * expected,
          name + ": crack faces have twice the crack length");
    check(split_ok, name + ": vertices split except at tips inside");
  }


  /**
   * The checks that hold for every mesh of this scene; the figures for
   * doc/validation.md are recorded under @p key.
   */
  void
  check_mesh(const BlockMesh &mesh, const std::string &key)
  {
    const std::vector<std::string> names      = {"ring",
                                                 "cracked",
                                                 "rock.0",
                                                 "rock.1",
                                                 "rock.2",
                                                 "rock.3",
                                                 "slab.0",
                                                 "slab.1"};
    const std::vector<double>      exact_area = {
           0.96, 1., 0.25, 0.25, 0.25, 0.25, 0.48, 0.48};
    const std::vector<unsigned int> materials = {1, 2, 3, 3, 3, 3, 4, 4};
    check(mesh.block_names == names, "block names");
    check(mesh.cell_block.size() == mesh.triangles.size() &&
            mesh.cell_material.size() == mesh.triangles.size(),
          "one block and material per cell");
    if (mesh.block_names != names)
      return;

    const Point<2>            sharp_corner(4., 0.2);
    std::vector<double>       area(names.size(), 0.);
    std::vector<unsigned int> n_cells(names.size(), 0);
    std::vector<double>       min_angle(names.size(), 180.);
    std::vector<double>       max_angle(names.size(), 0.);
    unsigned int              n_excluded  = 0;
    bool                      ccw         = true;
    bool                      material_ok = true;
    std::vector<int>          vertex_block(mesh.vertices.size(), -1);
    bool                      shared = false;
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      {
        const auto        &t = mesh.triangles[c];
        const unsigned int b = mesh.cell_block[c];
        const double       a = signed_area(mesh, t);
        ccw                  = ccw && a > 0.;
        material_ok = material_ok && mesh.cell_material[c] == materials[b];
        area[b] += a;
        ++n_cells[b];
        for (const unsigned int v : t)
          {
            shared =
              shared || (vertex_block[v] != -1 && vertex_block[v] != int(b));
            vertex_block[v] = b;
          }
        if (std::any_of(t.begin(), t.end(), [&](const unsigned int v) {
              return mesh.vertices[v].distance(sharp_corner) <= 1e-12;
            }))
          {
            ++n_excluded;
            continue;
          }
        for (const double angle : angles(mesh, t))
          {
            min_angle[b] = std::min(min_angle[b], angle);
            max_angle[b] = std::max(max_angle[b], angle);
          }
      }
    check(ccw, "all triangles counter-clockwise");
    check(material_ok, "material ids");
    check(!shared, "no vertex shared between blocks");
    check(std::find(vertex_block.begin(), vertex_block.end(), -1) ==
            vertex_block.end(),
          "every vertex used");
    // Vertex numbers of a block form one contiguous range.
    bool contiguous = true;
    for (unsigned int v = 1; v < vertex_block.size(); ++v)
      contiguous = contiguous && vertex_block[v] >= vertex_block[v - 1];
    check(contiguous, "every block has its own range of vertex numbers");

    double region_area   = 0.;
    double largest_error = 0.;
    for (unsigned int b = 0; b < names.size(); ++b)
      {
        const double error = std::abs(area[b] - exact_area[b]) / exact_area[b];
        largest_error      = std::max(largest_error, error);
        std::cout << "  " << std::setw(8) << std::left << names[b] << std::right
                  << " cells " << std::setw(4) << n_cells[b] << "  area "
                  << area[b] << "  angles [" << std::fixed
                  << std::setprecision(3) << min_angle[b] << ", "
                  << max_angle[b] << "]" << std::defaultfloat
                  << std::setprecision(6) << std::endl;
        check(error <= 1e-12, names[b] + ": area");
        check(min_angle[b] >= 30. - 1e-6, names[b] + ": minimum angle");
        check(max_angle[b] <= 120. + 1e-6, names[b] + ": maximum angle");
        if (names[b].rfind("rock.", 0) == 0)
          region_area += area[b];
      }
    std::cout << "  largest relative area error " << largest_error << std::endl;
    std::cout << "  triangles at (4, 0.2) left out of the angle check: "
              << n_excluded << std::endl;
    ndda_tests::record(key + ".blocks", unsigned(mesh.block_names.size()));
    ndda_tests::record(key + ".triangles", unsigned(mesh.triangles.size()));
    ndda_tests::record(key + ".crack_edges", unsigned(mesh.crack_edges.size()));
    ndda_tests::record(key + ".area_error", largest_error, 2);
    ndda_tests::record(key + ".min_angle",
                       *std::min_element(min_angle.begin(), min_angle.end()));
    ndda_tests::record(key + ".max_angle",
                       *std::max_element(max_angle.begin(), max_angle.end()));
    ndda_tests::record(key + ".excluded", n_excluded);
    check(std::abs(region_area - 1.) <= 1e-12, "rock: blocks fill the region");
    // The target number of cells is met roughly.
    check(n_cells[0] >= 200 && n_cells[0] <= 800,
          "ring: about 400 cells as asked");

    // Required vertices: inside rock.0; on the joint between rock.1 and
    // rock.3, so in both; on the boundary of ring.
    check(copies_at(mesh, block_index(mesh, "rock.0"), Point<2>(0.25, 0.25)) ==
            1,
          "required vertex inside a block");
    check(copies_at(mesh, block_index(mesh, "rock.1"), Point<2>(0.75, 0.5)) ==
              1 &&
            copies_at(mesh, block_index(mesh, "rock.3"), Point<2>(0.75, 0.5)) ==
              1,
          "required vertex on a joint");
    check(copies_at(mesh, block_index(mesh, "ring"), Point<2>(2.5, 0.)) == 1,
          "required vertex on a block boundary");
  }
} // namespace



int
main()
{
  std::cout << std::setprecision(6);

  std::cout << "dangling joints kept as cracks:" << std::endl;
  const BlockMesh mesh = mesh_scene(make_scene(true));
  std::cout << "  " << mesh.block_names.size() << " blocks, "
            << mesh.triangles.size() << " triangles, " << mesh.vertices.size()
            << " vertices, " << mesh.crack_edges.size() << " crack edges"
            << std::endl;
  check_mesh(mesh, "geometry_cutting.kept");
  check_crack(mesh, "rock.1", {Point<2>(0.5, 0.25), Point<2>(0.8, 0.25)}, 2, 1);
  check_crack(mesh, "cracked", {Point<2>(4, 0.2), Point<2>(4.5, 0.7)}, 2, 1);
  check_crack(mesh, "slab.0", {Point<2>(0.1, 2.8), Point<2>(0.3, 2.8)}, 1, 1);

  const BlockMesh again = mesh_scene(make_scene(true));
  const bool      same  = again.vertices == mesh.vertices &&
                    again.triangles == mesh.triangles &&
                    again.crack_edges == mesh.crack_edges;
  std::cout << "  same mesh for the same input: " << (same ? "yes" : "no")
            << std::endl;
  check(same, "deterministic");

  std::cout << "dangling joints dropped:" << std::endl;
  const BlockMesh dropped = mesh_scene(make_scene(false));
  std::cout << "  " << dropped.block_names.size() << " blocks, "
            << dropped.triangles.size() << " triangles, "
            << dropped.vertices.size() << " vertices, "
            << dropped.crack_edges.size() << " crack edges" << std::endl;
  check_mesh(dropped, "geometry_cutting.dropped");
  // Only the explicit crack of "cracked" is left.
  check_crack(dropped, "cracked", {Point<2>(4, 0.2), Point<2>(4.5, 0.7)}, 2, 1);
  const unsigned int cracked      = block_index(dropped, "cracked");
  bool               only_cracked = true;
  for (const auto &e : dropped.crack_edges)
    for (unsigned int c = 0; c < dropped.triangles.size(); ++c)
      if (std::count(dropped.triangles[c].begin(),
                     dropped.triangles[c].end(),
                     e[0]) > 0)
        only_cracked = only_cracked && dropped.cell_block[c] == cracked;
  check(only_cracked, "no crack edges but the explicit crack");
  check(copies_at(dropped,
                  block_index(dropped, "rock.1"),
                  Point<2>(0.5, 0.25)) <= 1,
        "dropped joint: no split vertex at its base");

  std::cout << (n_failures == 0 ? "OK" : "FAILED") << std::endl;
  return n_failures == 0 ? 0 : 1;
}
