// SPDX-License-Identifier: GPL-3.0-or-later
//
// CrackableMesh::crack(): node splitting that rebuilds the triangulation
// (thesis section 5.3, DESIGN.md decision 6), on structured grids of unit
// squares, each cut into two counter-clockwise triangles by its diagonal
// from lower left to upper right. Edges are named by the coordinates of
// their ends. The cases:
//  - interior_tips: one edge with both ends inside the block: no new
//    vertex (thesis figure 5.4), the edge becomes two boundary edges of a
//    loop without area.
//  - boundary_to_tip: one edge from the boundary to an interior vertex:
//    one new vertex (figure 5.5b).
//  - corner_chord: the diagonal of a corner square, boundary to boundary:
//    two new vertices (figure 5.5c), the corner triangle becomes a block.
//  - ring_cut: a ring (grid with a hole), cut once from the outer boundary
//    to the hole: two new vertices, still one block, two loops become one.
//  - boundary_tip_path: a path from the boundary ending inside the block.
//  - across: a path from boundary to boundary: the block splits in two.
//  - crossing: two crossing paths with interior tips: the centre vertex
//    gets four copies (three new), the tips none.
//  - cross_through: two crossing paths from boundary to boundary: four
//    blocks.
//  - growing: the path of boundary_tip_path grown edge by edge until it
//    reaches the other side, then one half cut again (names grid.1,
//    grid.2).
//  - two_blocks: a crack through the second of two blocks: only it splits,
//    the new block is appended.
// After each crack: check() accepts the mesh, the area is kept, each new
// vertex sits on its source vertex, a vertex field and a P2 vector field
// are carried over exactly, cells keep vertices, material and block,
// boundary edges grow by two per cracked edge (in ndda's list and in
// deal.II's faces), the boundary loops close and their areas add up to
// each block's area. Refused edges are checked by their message. Last, a
// timing of one crack in meshes of 1e4 and 1e5 cells (printed, not
// checked).

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools_interpolate.h>

#include <ndda/mesh/boundary_edges.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/mesh/state_transfer.h>
#include <ndda/mesh/topology.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "tests.h"

using namespace ndda;
using dealii::Point;
using dealii::Tensor;
using ndda_tests::check;

namespace
{
  /**
   * Grid of nx x ny unit squares with the lower left corner at (x0, 0),
   * one block named @p name, material id c % 3 for triangle c (so that a
   * reordering of cells would show). Squares with both indices in
   * [hole_begin, hole_end) are left out; vertices no triangle uses are
   * dropped.
   */
  void
  add_grid(geometry::BlockMesh &mesh,
           const unsigned int   nx,
           const unsigned int   ny,
           const std::string   &name,
           const double         x0         = 0.,
           const unsigned int   hole_begin = 0,
           const unsigned int   hole_end   = 0)
  {
    const unsigned int block = mesh.block_names.size();
    mesh.block_names.push_back(name);
    std::vector<unsigned int> index((nx + 1) * (ny + 1),
                                    dealii::numbers::invalid_unsigned_int);
    const auto v = [&](const unsigned int i, const unsigned int j) {
      unsigned int &k = index[j * (nx + 1) + i];
      if (k == dealii::numbers::invalid_unsigned_int)
        {
          k = mesh.vertices.size();
          mesh.vertices.emplace_back(x0 + i, j);
        }
      return k;
    };
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        if (!(i >= hole_begin && i < hole_end && j >= hole_begin &&
              j < hole_end))
          {
            mesh.triangles.push_back({{v(i, j), v(i + 1, j), v(i + 1, j + 1)}});
            mesh.triangles.push_back({{v(i, j), v(i + 1, j + 1), v(i, j + 1)}});
          }
    mesh.cell_block.resize(mesh.triangles.size(), block);
    for (unsigned int c = mesh.cell_material.size(); c < mesh.triangles.size();
         ++c)
      mesh.cell_material.push_back(c % 3);
  }


  geometry::BlockMesh
  grid(const unsigned int nx,
       const unsigned int ny,
       const unsigned int hole_begin = 0,
       const unsigned int hole_end   = 0)
  {
    geometry::BlockMesh mesh;
    add_grid(mesh, nx, ny, "grid", 0., hole_begin, hole_end);
    return mesh;
  }


  /**
   * The vertex at (x, y) of block @p block (the copy that lies in that
   * block and, of several copies, the one with the lowest index).
   */
  unsigned int
  vertex_at(const CrackableMesh &mesh,
            const double         x,
            const double         y,
            const unsigned int   block = 0)
  {
    const auto &m = mesh.get_block_mesh();
    for (unsigned int c = 0; c < m.triangles.size(); ++c)
      if (m.cell_block[c] == block)
        for (const unsigned int v : m.triangles[c])
          if (m.vertices[v] == Point<2>(x, y))
            {
              unsigned int lowest = v;
              for (unsigned int d = 0; d < m.triangles.size(); ++d)
                if (m.cell_block[d] == block)
                  for (const unsigned int w : m.triangles[d])
                    if (m.vertices[w] == Point<2>(x, y))
                      lowest = std::min(lowest, w);
              return lowest;
            }
    check(false,
          "no vertex at " + std::to_string(x) + ", " + std::to_string(y));
    return 0;
  }


  /** A path through the points (x, y) given as a flat list. */
  std::vector<std::array<unsigned int, 2>>
  path(const CrackableMesh         &mesh,
       const std::vector<Point<2>> &points,
       const unsigned int           block = 0)
  {
    std::vector<std::array<unsigned int, 2>> edges;
    for (unsigned int i = 0; i + 1 < points.size(); ++i)
      edges.push_back(
        {{vertex_at(mesh, points[i][0], points[i][1], block),
          vertex_at(mesh, points[i + 1][0], points[i + 1][1], block)}});
    return edges;
  }


  /** A smooth vertex field, e.g. a displacement. */
  Tensor<1, 2>
  field(const Point<2> &x)
  {
    Tensor<1, 2> u;
    u[0] = std::sin(x[0]) + 2. * x[1];
    u[1] = x[0] * x[1] - 0.25 * x[1] * x[1];
    return u;
  }


  double
  triangle_area(const geometry::BlockMesh &mesh, const unsigned int c)
  {
    const auto &t = mesh.triangles[c];
    const auto  a = mesh.vertices[t[1]] - mesh.vertices[t[0]];
    const auto  b = mesh.vertices[t[2]] - mesh.vertices[t[0]];
    return 0.5 * (a[0] * b[1] - a[1] * b[0]);
  }


  unsigned int
  n_deal_boundary_faces(const dealii::Triangulation<2> &triangulation)
  {
    unsigned int n = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        n += cell->face(f)->at_boundary() ? 1 : 0;
    return n;
  }


  /**
   * The boundary loops of @p mesh, checked: every boundary edge in one
   * loop, consecutive edges joined, one block per loop, one outer loop
   * (positive area) per block, loop areas adding up to the block's area.
   */
  std::vector<topology::BoundaryLoop>
  checked_loops(const CrackableMesh &mesh, const std::string &name)
  {
    const auto &m     = mesh.get_block_mesh();
    const auto  edges = boundary_edges(m);
    const auto  loops = topology::boundary_loops(m, edges);

    std::vector<unsigned int> n_in_loop(edges.size(), 0);
    std::vector<double>       loop_area(mesh.n_blocks(), 0.);
    std::vector<unsigned int> n_outer(mesh.n_blocks(), 0);
    for (const auto &loop : loops)
      {
        for (unsigned int i = 0; i < loop.edges.size(); ++i)
          {
            const auto &e    = edges[loop.edges[i]];
            const auto &next = edges[loop.edges[(i + 1) % loop.edges.size()]];
            ++n_in_loop[loop.edges[i]];
            check(e.v1 == next.v0 && e.block == loop.block,
                  name + ": loop edges joined, one block per loop");
          }
        loop_area[loop.block] += loop.signed_area;
        n_outer[loop.block] += loop.signed_area > 0. ? 1 : 0;
      }
    check(std::all_of(n_in_loop.begin(),
                      n_in_loop.end(),
                      [](const unsigned int n) { return n == 1; }),
          name + ": every boundary edge in exactly one loop");
    std::vector<double> block_area(mesh.n_blocks(), 0.);
    for (unsigned int c = 0; c < m.triangles.size(); ++c)
      block_area[m.cell_block[c]] += triangle_area(m, c);
    for (unsigned int b = 0; b < mesh.n_blocks(); ++b)
      {
        check(n_outer[b] == 1, name + ": one outer loop per block");
        check(std::abs(loop_area[b] - block_area[b]) <= 1e-14 * block_area[b],
              name + ": loop areas add up to the block area");
      }
    return loops;
  }


  /** What a crack must give. */
  struct Expected
  {
    unsigned int new_vertices;
    unsigned int blocks;
    unsigned int loops;
    /// Boundary edges added: two per cracked edge whose faces come apart.
    unsigned int new_boundary_edges;
  };


  /**
   * Crack @p mesh along @p edges and check everything that must hold
   * after a crack; print what was measured.
   */
  CrackResult
  run(const std::string                              &name,
      CrackableMesh                                  &mesh,
      const std::vector<std::array<unsigned int, 2>> &edges,
      const Expected                                 &expected)
  {
    const geometry::BlockMesh before            = mesh.get_block_mesh();
    const double              area              = mesh.area();
    const unsigned int        n_boundary_before = boundary_edges(before).size();
    const unsigned int        n_faces_before =
      n_deal_boundary_faces(mesh.get_triangulation());
    std::vector<Tensor<1, 2>> u_before;
    for (const auto &x : before.vertices)
      u_before.push_back(field(x));

    const CrackResult result = mesh.crack(edges);

    const auto        &after = mesh.get_block_mesh();
    const unsigned int n_old = before.vertices.size();
    const unsigned int n_new = after.vertices.size();
    CrackableMesh::check(after);

    // Vertices: old ones keep their index, copies sit on their source.
    check(result.vertex_origin.size() == n_new &&
            result.new_vertices.size() == n_new - n_old &&
            n_new - n_old == expected.new_vertices,
          name + ": number of new vertices");
    for (unsigned int v = 0; v < n_new; ++v)
      check((v < n_old ? result.vertex_origin[v] == v :
                         result.new_vertices[v - n_old] == v) &&
              after.vertices[v] == before.vertices[result.vertex_origin[v]] &&
              mesh.get_triangulation().get_vertices()[v] == after.vertices[v],
            name + ": vertex map and positions");
    const auto u_after =
      state_transfer::transfer_vertex_data(u_before, result.vertex_origin);
    for (unsigned int v = 0; v < n_new; ++v)
      check(u_after[v] == field(after.vertices[v]),
            name + ": vertex field carried over");

    // Cells: same corners (through the map), material, block origin.
    for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        for (unsigned int j = 0; j < 3; ++j)
          check(result.vertex_origin[cell->vertex_index(j)] ==
                  before.triangles[c][j],
                name + ": cell keeps its corners");
        check(cell->material_id() == before.cell_material[c] &&
                result.cell_block[c] == mesh.block_of_cell(c) &&
                result.block_origin[mesh.block_of_cell(c)] ==
                  before.cell_block[c] &&
                triangle_area(after, c) == triangle_area(before, c),
              name + ": cell keeps material, block and area");
      }
    check(std::abs(mesh.area() - area) <= 1e-14 * area, name + ": area kept");

    // Blocks.
    check(mesh.n_blocks() == expected.blocks &&
            result.block_origin.size() == mesh.n_blocks() &&
            result.block_children.size() == before.block_names.size(),
          name + ": number of blocks");
    for (unsigned int b = 0; b < before.block_names.size(); ++b)
      {
        check(result.block_children[b][0] == b &&
                mesh.get_block_names()[b] == before.block_names[b],
              name + ": a block keeps its index and name");
        for (const unsigned int child : result.block_children[b])
          check(result.block_origin[child] == b &&
                  (child == b || mesh.get_block_names()[child].rfind(
                                   before.block_names[b] + ".", 0) == 0),
                name + ": children of a block are named after it");
      }

    // Cracked edges: both faces lie on the old edge, with their cell on the
    // left, and are crack faces. Faces that came apart are boundary edges;
    // faces that share both vertices (both tips inside) are not yet.
    const auto boundary = boundary_edges(after);
    std::map<std::array<unsigned int, 2>, unsigned int> cell_of_edge;
    for (const auto &e : boundary)
      cell_of_edge[{{e.v0, e.v1}}] = e.cell;
    unsigned int n_closed = 0;
    for (const auto &e : result.cracked_edges)
      {
        const bool closed =
          e.faces[0][0] == e.faces[1][1] && e.faces[0][1] == e.faces[1][0];
        n_closed += closed ? 1 : 0;
        for (unsigned int i = 0; i < 2; ++i)
          {
            const auto        &f = e.faces[i];
            const auto        &t = after.triangles[e.cells[i]];
            const unsigned int j =
              std::find(t.begin(), t.end(), f[0]) - t.begin();
            check(j < 3 && t[(j + 1) % 3] == f[1] &&
                    result.vertex_origin[f[0]] == e.old_vertices[i] &&
                    result.vertex_origin[f[1]] == e.old_vertices[1 - i] &&
                    mesh.is_cracked(f[0], f[1]),
                  name + ": crack faces are sides of their cells");
            const auto it = cell_of_edge.find(f);
            check(closed ||
                    (it != cell_of_edge.end() && it->second == e.cells[i]),
                  name + ": open crack faces are boundary edges");
          }
      }
    check(boundary.size() == n_boundary_before + expected.new_boundary_edges &&
            n_deal_boundary_faces(mesh.get_triangulation()) ==
              n_faces_before + expected.new_boundary_edges,
          name + ": boundary edges added (ndda and deal.II)");
    const unsigned int n_cracked = result.cracked_edges.size();

    const auto loops = checked_loops(mesh, name);
    check(loops.size() == expected.loops, name + ": number of loops");

    std::cout << name << ": vertices " << n_old << " -> " << n_new
              << ", cracked edges " << n_cracked << " (" << n_closed
              << " closed), boundary edges " << n_boundary_before << " -> "
              << boundary.size() << ", loops " << loops.size() << " (areas";
    for (const auto &loop : loops)
      std::cout << " " << loop.signed_area;
    std::cout << "), blocks";
    for (const auto &b : mesh.get_block_names())
      std::cout << " '" << b << "'";
    std::cout << ", area change " << mesh.area() - area << std::endl;
    return result;
  }


  CrackResult
  run(const std::string                      &name,
      const geometry::BlockMesh              &start,
      const std::vector<std::vector<double>> &paths,
      const Expected                         &expected)
  {
    CrackableMesh mesh;
    mesh.build(start);
    std::vector<std::array<unsigned int, 2>> edges;
    for (const auto &p : paths)
      {
        std::vector<Point<2>> points;
        for (unsigned int i = 0; i + 1 < p.size(); i += 2)
          points.emplace_back(p[i], p[i + 1]);
        const auto part = path(mesh, points);
        edges.insert(edges.end(), part.begin(), part.end());
      }
    return run(name, mesh, edges, expected);
  }


  /** The edge is refused with a message that contains @p expected. */
  void
  refused(CrackableMesh                     &mesh,
          const std::array<unsigned int, 2> &edge,
          const std::string                 &expected)
  {
    const unsigned int n_vertices = mesh.get_block_mesh().vertices.size();
    std::string        message;
    try
      {
        mesh.crack({edge});
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream out;
        e.print_info(out);
        message = out.str();
      }
    std::cout << "refused (" << edge[0] << ", " << edge[1] << "): " << message;
    check(message.find(expected) != std::string::npos,
          "refused with '" + expected + "'");
    check(mesh.get_block_mesh().vertices.size() == n_vertices,
          "a refused crack changes nothing");
  }


  /** A vector field that P2 does not represent exactly. */
  class Quadratic : public dealii::Function<2>
  {
  public:
    Quadratic()
      : dealii::Function<2>(2)
    {}

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      return component == 0 ? p[0] * p[0] + std::sin(p[1]) :
                              p[0] * p[1] - p[1] * p[1];
    }
  };


  /**
   * A P2 vector field interpolated on the mesh before the crack and carried
   * over by cell degrees of freedom equals the field interpolated on the
   * mesh after it.
   */
  void
  dof_transfer()
  {
    CrackableMesh mesh;
    mesh.build(grid(4, 4));
    const dealii::FESystem<2>  fe(dealii::FE_SimplexP<2>(2), 2);
    const dealii::MappingFE<2> mapping(dealii::FE_SimplexP<2>(1));
    dealii::DoFHandler<2>      dof_handler(mesh.get_triangulation());
    const Quadratic            f;

    const auto cell_dofs = [&]() {
      std::vector<dealii::types::global_dof_index> all,
        one(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(one);
          all.insert(all.end(), one.begin(), one.end());
        }
      return all;
    };

    dof_handler.distribute_dofs(fe);
    dealii::Vector<double> old_values(dof_handler.n_dofs());
    dealii::VectorTools::interpolate(mapping, dof_handler, f, old_values);
    const auto         old_cell_dofs = cell_dofs();
    const unsigned int n_old_dofs    = dof_handler.n_dofs();

    const auto result =
      mesh.crack(path(mesh, {{0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}}));
    const unsigned int n_dofs_after_crack = dof_handler.n_dofs();

    dof_handler.distribute_dofs(fe);
    dealii::Vector<double> new_values(dof_handler.n_dofs()),
      interpolated(dof_handler.n_dofs());
    state_transfer::transfer_dof_values(old_cell_dofs,
                                        old_values,
                                        cell_dofs(),
                                        new_values);
    dealii::VectorTools::interpolate(mapping, dof_handler, f, interpolated);
    interpolated -= new_values;

    std::cout << "dof_transfer (P2 x 2): dofs " << n_old_dofs
              << ", after crack() " << n_dofs_after_crack
              << ", after distribute_dofs() " << dof_handler.n_dofs()
              << ", max difference to interpolation "
              << interpolated.linfty_norm() << std::endl;
    // Each new vertex and each cracked edge's midpoint adds 2 dofs.
    check(n_dofs_after_crack == 0, "crack() clears the attached DoFHandler");
    check(dof_handler.n_dofs() ==
            n_old_dofs +
              2 * (result.new_vertices.size() + result.cracked_edges.size()),
          "number of dofs after the crack");
    // Exact but for the rounding of support points that interpolate()
    // computes from different cells.
    check(interpolated.linfty_norm() <= 1e-14 * old_values.linfty_norm(),
          "dof values carried over");
  }


  /**
   * Time of one crack of an interior edge in an n x n grid (2 n^2 cells),
   * and of its stages on the same mesh: the vertex split, the topology
   * (side index and components), check(), and build() (which includes
   * check() and deal.II's create_triangulation()).
   */
  void
  timing(const unsigned int n)
  {
    using clock   = std::chrono::steady_clock;
    const auto ms = [](const clock::duration d) {
      return std::chrono::duration<double, std::milli>(d).count();
    };
    const geometry::BlockMesh start = grid(n, n);
    CrackableMesh             mesh;
    mesh.build(start);

    // Interior edges along the middle row, one crack each: each grows the
    // crack by one edge, away from the boundary. Tips are not split, so
    // the vertex indices found now stay valid.
    const unsigned int                       n_cracks = 5;
    std::vector<std::array<unsigned int, 2>> edges;
    for (unsigned int k = 0; k < n_cracks; ++k)
      edges.push_back({{vertex_at(mesh, n / 2 + k, n / 2),
                        vertex_at(mesh, n / 2 + k + 1, n / 2)}});

    geometry::BlockMesh split = start;
    auto                t0    = clock::now();
    geometry::split_vertices_along_edges(split, {edges[0]});
    const double split_ms = ms(clock::now() - t0);
    t0                    = clock::now();
    unsigned int n_components;
    topology::connected_components(topology::HalfEdges(split.triangles,
                                                       split.vertices.size()),
                                   split.triangles.size(),
                                   n_components);
    const double topology_ms = ms(clock::now() - t0);
    t0                       = clock::now();
    CrackableMesh::check(split);
    const double check_ms = ms(clock::now() - t0);
    t0                    = clock::now();
    mesh.build(start);
    const double build_ms = ms(clock::now() - t0);

    t0 = clock::now();
    for (const auto &edge : edges)
      mesh.crack({edge});
    const double crack_ms = ms(clock::now() - t0) / n_cracks;
    check(n_components == 1 && mesh.n_blocks() == 1 &&
            mesh.get_block_mesh().vertices.size() ==
              start.vertices.size() + n_cracks - 1,
          "timing: cracks applied");
    std::cout << "timing: " << start.triangles.size() << " cells, "
              << start.vertices.size() << " vertices: crack of one edge "
              << crack_ms << " ms; stages: split " << split_ms
              << " ms, topology " << topology_ms << " ms, check " << check_ms
              << " ms, build (with check) " << build_ms << " ms" << std::endl;
  }
} // namespace



int
main()
{
  try
    {
      std::cout << std::setprecision(6);

      run("interior_tips", grid(4, 4), {{1, 2, 2, 2}}, {0, 1, 1, 0});
      run("boundary_to_tip", grid(4, 4), {{0, 2, 1, 2}}, {1, 1, 1, 2});
      run("corner_chord", grid(4, 4), {{0, 3, 1, 4}}, {2, 2, 2, 2});
      run("ring_cut", grid(4, 4, 1, 3), {{0, 2, 1, 2}}, {2, 1, 1, 2});
      run("boundary_tip_path", grid(4, 4), {{0, 2, 1, 2, 2, 2}}, {2, 1, 1, 4});
      run("across", grid(4, 4), {{0, 2, 1, 2, 2, 2, 3, 2, 4, 2}}, {5, 2, 2, 8});
      run("crossing",
          grid(4, 4),
          {{1, 2, 2, 2, 3, 2}, {2, 1, 2, 2, 2, 3}},
          {3, 1, 2, 8});
      run("cross_through",
          grid(4, 4),
          {{0, 2, 1, 2, 2, 2, 3, 2, 4, 2}, {2, 0, 2, 1, 2, 2, 2, 3, 2, 4}},
          {11, 4, 4, 16});

      // A closed crack (both tips inside) opens when it grows: its tip at
      // (2, 2) is split, and both edges become two boundary edges each.
      {
        CrackableMesh mesh;
        mesh.build(grid(4, 4));
        run("closed_1", mesh, path(mesh, {{1, 2}, {2, 2}}), {0, 1, 1, 0});
        run("closed_2", mesh, path(mesh, {{2, 2}, {3, 2}}), {1, 1, 2, 4});
      }

      // A crack that grows edge by edge, then a second crack in one half.
      {
        CrackableMesh mesh;
        mesh.build(grid(4, 4));
        run("growing_1",
            mesh,
            path(mesh, {{0, 2}, {1, 2}, {2, 2}}),
            {2, 1, 1, 4});
        run("growing_2", mesh, path(mesh, {{2, 2}, {3, 2}}), {1, 1, 1, 2});
        const auto result =
          run("growing_3", mesh, path(mesh, {{3, 2}, {4, 2}}), {2, 2, 2, 2});
        check(mesh.get_block_names()[1] == "grid.1" &&
                result.block_children[0] == std::vector<unsigned int>{0, 1} &&
                mesh.block_of_cell(0) == 0,
              "growing: the half with cell 0 keeps block 0");
        const auto second = run("growing_4",
                                mesh,
                                path(mesh, {{2, 0}, {2, 1}, {2, 2}}),
                                {3, 3, 3, 4});
        check(mesh.get_block_names()[2] == "grid.2" &&
                second.block_children[0] == std::vector<unsigned int>{0, 2} &&
                second.block_children[1] == std::vector<unsigned int>{1},
              "growing: the next split-off block is grid.2");
      }

      // Two blocks: only the cracked one splits; the new block comes last.
      {
        geometry::BlockMesh start;
        add_grid(start, 2, 2, "left");
        add_grid(start, 2, 2, "right", 3.);
        CrackableMesh mesh;
        mesh.build(start);
        const auto result = run("two_blocks",
                                mesh,
                                path(mesh, {{3, 1}, {4, 1}, {5, 1}}, 1),
                                {3, 3, 3, 4});
        check(mesh.get_block_names()[2] == "right.1" &&
                result.block_children[0] == std::vector<unsigned int>{0} &&
                result.block_children[1] == std::vector<unsigned int>{1, 2},
              "two_blocks: block 1 splits into 1 and 2");
      }

      // Refused edges.
      {
        CrackableMesh mesh;
        mesh.build(grid(4, 4));
        refused(mesh,
                {{vertex_at(mesh, 0, 0), vertex_at(mesh, 1, 0)}},
                "lies on the boundary of block 'grid'");
        refused(mesh,
                {{vertex_at(mesh, 0, 0), vertex_at(mesh, 2, 2)}},
                "is not an edge of the mesh");
        refused(mesh, {{vertex_at(mesh, 1, 1), 1000}}, "does not exist");
        refused(mesh,
                {{vertex_at(mesh, 1, 1), vertex_at(mesh, 1, 1)}},
                "joins a vertex to itself");
        // A closed crack (both tips inside) and an open one.
        const auto closed = path(mesh, {{1, 2}, {2, 2}});
        mesh.crack(closed);
        refused(mesh, closed[0], "is a crack already");
        const auto open = path(mesh, {{0, 1}, {1, 1}});
        mesh.crack(open);
        refused(mesh, open[0], "is a crack already");
        refused(mesh,
                {{vertex_at(mesh, 0, 0), vertex_at(mesh, 0, 1)}},
                "lies on the boundary of block 'grid'");
      }

      dof_transfer();

      timing(71);
      timing(224);
    }
  catch (const std::exception &e)
    {
      std::cout << "FAILED with an exception: " << e.what() << std::endl;
      return 1;
    }
  std::cout << "OK" << std::endl;
  return 0;
}
