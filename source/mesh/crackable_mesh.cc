// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/parallel.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <ndda/mesh/crackable_mesh.h>
#include <ndda/mesh/topology.h>
#include <ndda/parallel/shared_mesh.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_set>

namespace ndda
{
  namespace
  {
    /** Key of an undirected edge. */
    std::uint64_t
    edge_key(const unsigned int a, const unsigned int b)
    {
      return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
    }


    double
    signed_area(const std::vector<Point<2>>       &vertices,
                const std::array<unsigned int, 3> &t)
    {
      const Tensor<1, 2> a = vertices[t[1]] - vertices[t[0]];
      const Tensor<1, 2> b = vertices[t[2]] - vertices[t[0]];
      return 0.5 * (a[0] * b[1] - a[1] * b[0]);
    }

    std::string
    describe(const geometry::BlockMesh &mesh, const unsigned int cell)
    {
      std::ostringstream out;
      out << "triangle " << cell << " (";
      for (unsigned int v = 0; v < 3; ++v)
        out << (v > 0 ? "; " : "") << mesh.vertices[mesh.triangles[cell][v]];
      out << ")";
      return out.str();
    }



    /**
     * The edges @p edges of @p mesh, checked to be interior edges (two
     * triangles run through each, in opposite directions) that are not
     * cracks yet, as (smaller vertex, larger vertex, side of the triangle
     * on the left of smaller -> larger).
     */
    std::vector<std::array<unsigned int, 3>>
    checked_crack_edges(const CrackableMesh       &mesh,
                        const topology::HalfEdges &half_edges,
                        const std::vector<std::array<unsigned int, 2>> &edges)
    {
      const unsigned int n_vertices = mesh.get_block_mesh().vertices.size();
      std::vector<std::array<unsigned int, 3>> to_crack;
      to_crack.reserve(edges.size());
      for (const auto &e : edges)
        {
          const std::string edge = "Crack: the edge between vertices " +
                                   std::to_string(e[0]) + " and " +
                                   std::to_string(e[1]);
          AssertThrow(e[0] < n_vertices && e[1] < n_vertices,
                      ExcMessage(edge + " does not exist: the mesh has " +
                                 std::to_string(n_vertices) + " vertices."));
          AssertThrow(e[0] != e[1],
                      ExcMessage(edge + " joins a vertex to itself."));
          const unsigned int a     = std::min(e[0], e[1]);
          const unsigned int b     = std::max(e[0], e[1]);
          const auto        &x     = mesh.get_block_mesh().vertices;
          const std::string  where = edge + " (at " +
                                    Utilities::to_string(x[a][0]) + ", " +
                                    Utilities::to_string(x[a][1]) + " and " +
                                    Utilities::to_string(x[b][0]) + ", " +
                                    Utilities::to_string(x[b][1]) + ")";
          const unsigned int left  = half_edges.find(a, b);
          const unsigned int right = half_edges.find(b, a);
          AssertThrow(left != numbers::invalid_unsigned_int ||
                        right != numbers::invalid_unsigned_int,
                      ExcMessage(where + " is not an edge of the mesh."));
          AssertThrow(!mesh.is_cracked(a, b),
                      ExcMessage(where + " is a crack already."));
          const unsigned int side =
            left != numbers::invalid_unsigned_int ? left : right;
          AssertThrow(left != numbers::invalid_unsigned_int &&
                        right != numbers::invalid_unsigned_int,
                      ExcMessage(
                        where + " lies on the boundary of block '" +
                        mesh.get_block_names()[mesh.block_of_cell(side / 3)] +
                        "' (only triangle " + std::to_string(side / 3) +
                        " has it); only an interior edge, shared by "
                        "two triangles, can crack."));
          to_crack.push_back({{a, b, left}});
        }
      return to_crack;
    }



    /**
     * The blocks of @p mesh after a split: a block that fell apart keeps
     * its index for the part with its lowest cell (visiting the cells in
     * increasing order meets it first), and the other parts become new
     * blocks named "<name>.<k>". @p block_names are the names before;
     * @p result receives each block's origin and children.
     */
    void
    renumber_blocks(const std::vector<std::string> &block_names,
                    geometry::BlockMesh            &mesh,
                    CrackResult                    &result)
    {
      const unsigned int              n_cells  = mesh.triangles.size();
      const unsigned int              n_blocks = block_names.size();
      const topology::HalfEdges       new_half_edges(mesh.triangles,
                                               mesh.vertices.size());
      unsigned int                    n_components = 0;
      const std::vector<unsigned int> component =
        topology::connected_components(new_half_edges, n_cells, n_components);
      std::vector<unsigned int> block_of_component(
        n_components, numbers::invalid_unsigned_int);
      std::vector<bool>               block_kept(n_blocks, false);
      std::vector<unsigned int>       next_suffix(n_blocks, 1);
      std::unordered_set<std::string> names(block_names.begin(),
                                            block_names.end());
      result.block_origin.resize(n_blocks);
      std::iota(result.block_origin.begin(), result.block_origin.end(), 0u);
      result.block_children.resize(n_blocks);
      for (unsigned int b = 0; b < n_blocks; ++b)
        result.block_children[b] = {b};
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          unsigned int      &block     = block_of_component[component[c]];
          const unsigned int old_block = mesh.cell_block[c];
          if (block == numbers::invalid_unsigned_int)
            {
              if (!block_kept[old_block])
                {
                  block                 = old_block;
                  block_kept[old_block] = true;
                }
              else
                {
                  std::string name;
                  do
                    name = block_names[old_block] + "." +
                           std::to_string(next_suffix[old_block]++);
                  while (names.count(name) > 0);
                  names.insert(name);
                  block = mesh.block_names.size();
                  mesh.block_names.push_back(name);
                  result.block_origin.push_back(old_block);
                  result.block_children[old_block].push_back(block);
                }
            }
          // Blocks share no vertices, so no component spans two blocks.
          Assert(result.block_origin[block] == old_block, ExcInternalError());
          mesh.cell_block[c] = block;
        }
    }



    /**
     * Check that every triangle of @p mesh is counter-clockwise with
     * positive area on the positions @p initial (check() has looked at
     * the topology): refinement bisects in both geometries.
     */
    void
    check_initial_geometry(const geometry::BlockMesh   &mesh,
                           const std::vector<Point<2>> &initial)
    {
      double max_extent = 0;
      for (const auto &v : initial)
        max_extent = std::max({max_extent, std::abs(v[0]), std::abs(v[1])});
      for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
        AssertThrow(signed_area(initial, mesh.triangles[c]) >
                      1e-14 * max_extent * max_extent,
                    ExcMessage("Mesh: " + describe(mesh, c) +
                               " is not counter-clockwise with positive "
                               "area in the initial geometry."));
    }



    /**
     * refinement::bisect_to_size() with its error message started by
     * @p what.
     */
    refinement::RefineResult
    bisect(geometry::BlockMesh               &mesh,
           std::vector<Point<2>>             &initial,
           const RefineAfterCrack::SizeBound &size_bound,
           const unsigned int                 max_cells,
           const std::string                 &what)
    {
      try
        {
          return refinement::bisect_to_size(mesh,
                                            initial,
                                            size_bound,
                                            max_cells);
        }
      catch (const ExceptionBase &exc)
        {
          if (what.empty())
            throw;
          std::ostringstream info;
          exc.print_info(info);
          AssertThrow(false, ExcMessage(what + ": " + info.str()));
        }
      return {};
    }
  } // namespace



  void
  CrackableMesh::check(const geometry::BlockMesh &mesh)
  {
    const unsigned int n_cells = mesh.triangles.size();
    AssertThrow(n_cells > 0, ExcMessage("Mesh: the scene has no triangles."));
    AssertThrow(mesh.cell_block.size() == n_cells &&
                  mesh.cell_material.size() == n_cells,
                ExcMessage("Mesh: block or material ids missing."));

    double max_extent = 0;
    for (const auto &v : mesh.vertices)
      max_extent = std::max({max_extent, std::abs(v[0]), std::abs(v[1])});

    std::vector<unsigned int> vertex_block(mesh.vertices.size(),
                                           numbers::invalid_unsigned_int);
    // Sorted vertex triples with their triangle, to find duplicates.
    std::vector<std::array<unsigned int, 4>> sorted_triangles(n_cells);
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const auto &t = mesh.triangles[c];
        for (const unsigned int v : t)
          AssertThrow(v < mesh.vertices.size(),
                      ExcMessage("Mesh: " + std::to_string(c) +
                                 " refers to a vertex that does not exist."));
        AssertThrow(mesh.cell_block[c] < mesh.block_names.size(),
                    ExcMessage("Mesh: " + describe(mesh, c) +
                               " has no valid block."));
        const double area = signed_area(mesh.vertices, t);
        AssertThrow(area > 1e-14 * max_extent * max_extent,
                    ExcMessage(
                      "Mesh: " + describe(mesh, c) +
                      (area < 0 ? " is clockwise." : " has zero area.") +
                      " Every triangle must be counter-clockwise "
                      "with positive area."));
        auto &sorted = sorted_triangles[c];
        sorted       = {{t[0], t[1], t[2], c}};
        std::sort(sorted.begin(), sorted.begin() + 3);
        AssertThrow(sorted[0] != sorted[1] && sorted[1] != sorted[2],
                    ExcMessage("Mesh: " + describe(mesh, c) +
                               " repeats a vertex."));
        for (const unsigned int v : t)
          {
            if (vertex_block[v] == numbers::invalid_unsigned_int)
              vertex_block[v] = mesh.cell_block[c];
            AssertThrow(vertex_block[v] == mesh.cell_block[c],
                        ExcMessage(
                          "Mesh: vertex " + std::to_string(v) + " at " +
                          Utilities::to_string(mesh.vertices[v][0]) + ", " +
                          Utilities::to_string(mesh.vertices[v][1]) +
                          " is shared by two blocks. Blocks must "
                          "not share vertices."));
          }
      }
    std::sort(sorted_triangles.begin(), sorted_triangles.end());
    for (unsigned int i = 1; i < n_cells; ++i)
      AssertThrow(!std::equal(sorted_triangles[i].begin(),
                              sorted_triangles[i].begin() + 3,
                              sorted_triangles[i - 1].begin()),
                  ExcMessage("Mesh: " + describe(mesh, sorted_triangles[i][3]) +
                             " appears twice."));
    // All triangles are counter-clockwise, so an edge shared by more than
    // two triangles is run through twice in the same direction: the side
    // index refuses it.
    const topology::HalfEdges half_edges(mesh.triangles, mesh.vertices.size());
    for (unsigned int v = 0; v < vertex_block.size(); ++v)
      AssertThrow(vertex_block[v] != numbers::invalid_unsigned_int,
                  ExcMessage("Mesh: vertex " + std::to_string(v) +
                             " is not used by any triangle."));
  }



  CrackableMesh::CrackableMesh(const MPI_Comm communicator)
    : triangulation(make_scene_triangulation(communicator))
  {}



  void
  CrackableMesh::build(const geometry::BlockMesh &mesh)
  {
    check(mesh);
    initial_vertices = mesh.vertices;
    install(geometry::BlockMesh(mesh));
  }



  void
  CrackableMesh::install(geometry::BlockMesh &&mesh)
  {
    std::vector<CellData<2>> cells(mesh.triangles.size(), CellData<2>(3));
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      {
        for (unsigned int v = 0; v < 3; ++v)
          cells[c].vertices[v] = mesh.triangles[c][v];
        cells[c].material_id = mesh.cell_material[c];
      }
    // The same Triangulation object, refilled: a DoFHandler built on it
    // stays attached (and is cleared by deal.II's clear signal).
    triangulation->clear();
    triangulation->create_triangulation(mesh.vertices, cells, SubCellData());

    // deal.II keeps the order of cells and of their vertices; verify it,
    // since everything that follows relies on it.
    for (const auto &cell : triangulation->active_cell_iterators())
      for (unsigned int v = 0; v < 3; ++v)
        AssertThrow(cell->vertex_index(v) ==
                      mesh.triangles[cell->active_cell_index()][v],
                    ExcInternalError());

    block_mesh  = std::move(mesh);
    block_names = block_mesh.block_names;
    cell_block  = block_mesh.cell_block;
    crack_keys.clear();
    for (const auto &e : block_mesh.crack_edges)
      crack_keys.push_back(edge_key(e[0], e[1]));
    std::sort(crack_keys.begin(), crack_keys.end());
    crack_keys.erase(std::unique(crack_keys.begin(), crack_keys.end()),
                     crack_keys.end());
  }



  bool
  CrackableMesh::is_cracked(const unsigned int a, const unsigned int b) const
  {
    return std::binary_search(crack_keys.begin(),
                              crack_keys.end(),
                              edge_key(a, b));
  }



  CrackResult
  CrackableMesh::crack(const std::vector<std::array<unsigned int, 2>> &edges,
                       const RefineAfterCrack                         &refine)
  {
    const unsigned int n_vertices = block_mesh.vertices.size();

    // 1. Every edge must be an interior edge: two triangles run through it,
    // in opposite directions.
    const topology::HalfEdges half_edges(block_mesh.triangles, n_vertices);
    std::vector<std::array<unsigned int, 3>> to_crack =
      checked_crack_edges(*this, half_edges, edges);
    std::sort(to_crack.begin(), to_crack.end());
    to_crack.erase(std::unique(to_crack.begin(), to_crack.end()),
                   to_crack.end());

    // 2. Split the vertices by fans. Cells keep their index and their local
    // vertex order; only vertex indices change.
    geometry::BlockMesh                      mesh = block_mesh;
    std::vector<std::array<unsigned int, 2>> split_edges;
    split_edges.reserve(to_crack.size());
    for (const auto &e : to_crack)
      split_edges.push_back({{e[0], e[1]}});
    // A crack whose faces still share both vertices (both tips were inside
    // the block) is still shared by two triangles; fans must not join
    // across it when the crack grows.
    for (const auto &e : block_mesh.crack_edges)
      if (half_edges.find(e[1], e[0]) != numbers::invalid_unsigned_int)
        split_edges.push_back(e);
    CrackResult result;
    result.vertex_origin =
      geometry::split_vertices_along_edges(mesh, split_edges);
    for (unsigned int v = n_vertices; v < mesh.vertices.size(); ++v)
      result.new_vertices.push_back(v);

    // 3. Blocks that fell apart.
    renumber_blocks(block_names, mesh, result);

    // The two faces of every cracked edge. Side j of cell c is still side
    // j of cell c.
    for (const auto &e : to_crack)
      {
        const unsigned int sides[2] = {e[2], half_edges.twin(e[2])};
        CrackedEdge        cracked;
        cracked.old_vertices = {{e[0], e[1]}};
        for (unsigned int i = 0; i < 2; ++i)
          {
            const auto &t    = mesh.triangles[sides[i] / 3];
            cracked.cells[i] = sides[i] / 3;
            cracked.faces[i] = {{t[sides[i] % 3], t[(sides[i] + 1) % 3]}};
          }
        result.cracked_edges.push_back(cracked);
      }

    result.cell_block = mesh.cell_block;
    // A copied vertex started where its origin did.
    std::vector<Point<2>> initial(mesh.vertices.size());
    for (unsigned int v = 0; v < initial.size(); ++v)
      initial[v] = initial_vertices[result.vertex_origin[v]];

    // 4. Refine (RefineAfterCrack), check and rebuild.
    if (refine.size_bound)
      {
        auto refined = bisect(mesh,
                              initial,
                              refine.size_bound(mesh, initial),
                              refine.max_cells,
                              refine.what);
        if (refined.n_bisections > 0)
          result.refined = std::move(refined);
      }
    check(mesh);
    if (result.refined)
      check_initial_geometry(mesh, initial);
    initial_vertices.swap(initial);
    install(std::move(mesh));
    return result;
  }



  geometry::BlockMesh
  to_block_mesh(const Triangulation<2> &triangulation,
                const std::string      &name_prefix)
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      AssertThrow(cell->reference_cell() == ReferenceCells::Triangle,
                  ExcMessage("Mesh: cell " +
                             std::to_string(cell->active_cell_index()) +
                             " is not a triangle. ndda works on triangles "
                             "only."));

    // Blocks: connected components through edges of equal material id.
    const unsigned int        n_cells = triangulation.n_active_cells();
    std::vector<unsigned int> block(n_cells, numbers::invalid_unsigned_int);
    std::vector<types::material_id> block_material;
    for (const auto &start : triangulation.active_cell_iterators())
      {
        if (block[start->active_cell_index()] != numbers::invalid_unsigned_int)
          continue;
        const unsigned int b = block_material.size();
        block_material.push_back(start->material_id());
        std::vector<Triangulation<2>::active_cell_iterator> stack = {start};
        block[start->active_cell_index()]                         = b;
        while (!stack.empty())
          {
            const auto cell = stack.back();
            stack.pop_back();
            for (unsigned int f = 0; f < cell->n_faces(); ++f)
              if (!cell->at_boundary(f))
                {
                  const auto neighbor = cell->neighbor(f);
                  if (neighbor->material_id() == cell->material_id() &&
                      block[neighbor->active_cell_index()] ==
                        numbers::invalid_unsigned_int)
                    {
                      block[neighbor->active_cell_index()] = b;
                      stack.push_back(neighbor);
                    }
                }
          }
      }

    geometry::BlockMesh mesh;
    for (unsigned int b = 0; b < block_material.size(); ++b)
      mesh.block_names.push_back(name_prefix + std::to_string(b));

    // One vertex copy per (vertex, block).
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> copy;
    const auto &vertices = triangulation.get_vertices();
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const unsigned int          b = block[cell->active_cell_index()];
        std::array<unsigned int, 3> t;
        for (unsigned int v = 0; v < 3; ++v)
          {
            const auto key = std::make_pair(cell->vertex_index(v), b);
            auto       it  = copy.find(key);
            if (it == copy.end())
              {
                it = copy.emplace(key, mesh.vertices.size()).first;
                mesh.vertices.push_back(vertices[cell->vertex_index(v)]);
              }
            t[v] = it->second;
          }
        if (signed_area(mesh.vertices, t) < 0)
          std::swap(t[1], t[2]);
        mesh.triangles.push_back(t);
        mesh.cell_block.push_back(b);
        mesh.cell_material.push_back(cell->material_id());
      }
    return mesh;
  }



  void
  CrackableMesh::build(const Triangulation<2> &input)
  {
    build(to_block_mesh(input, "block "));
  }



  void
  CrackableMesh::read_msh(
    const std::string                               &filename,
    const std::function<unsigned int(unsigned int)> &material_of_tag)
  {
    // read_msh(std::istream&) keeps coincident nodes of different blocks
    // apart and keeps unnamed physical tags (DESIGN.md, measured facts).
    std::ifstream in(filename);
    AssertThrow(in.good(),
                ExcMessage("Geometry/Mesh file: cannot open '" + filename +
                           "'."));
    Triangulation<2> input;
    GridIn<2>        grid_in(input);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream message;
        exc.print_info(message);
        AssertThrow(false,
                    ExcMessage("Geometry/Mesh file: '" + filename +
                               "' cannot be read as a gmsh mesh of "
                               "triangles: " +
                               message.str()));
      }
    auto mesh = to_block_mesh(input, "block ");
    for (auto &material : mesh.cell_material)
      material = material_of_tag(material);
    build(mesh);
  }



  void
  CrackableMesh::move_vertices(const std::vector<Tensor<1, 2>> &displacement)
  {
    AssertDimension(displacement.size(), triangulation->n_vertices());
    // deal.II has no mutable access to its vertex array but through cell
    // accessors (step-18), which cost more than the whole stress update of
    // a P1 step. get_vertices() returns a reference to the triangulation's
    // own vertex vector; writing through it changes nothing else (no
    // cached geometry is kept by Triangulation<2> with a linear mapping).
    auto &vertices =
      const_cast<std::vector<Point<2>> &>(triangulation->get_vertices());
    for (unsigned int i = 0; i < vertices.size(); ++i)
      {
        vertices[i] += displacement[i];
        block_mesh.vertices[i] += displacement[i];
      }
  }



  void
  CrackableMesh::set_vertices(const std::vector<Point<2>> &positions)
  {
    AssertDimension(positions.size(), triangulation->n_vertices());
    // As move_vertices() does, through the triangulation's own vector.
    auto &vertices =
      const_cast<std::vector<Point<2>> &>(triangulation->get_vertices());
    vertices            = positions;
    block_mesh.vertices = positions;
  }



  refinement::RefineResult
  CrackableMesh::refine(const RefineAfterCrack::SizeBound &size_bound,
                        const unsigned int                 max_cells)
  {
    geometry::BlockMesh   mesh    = block_mesh;
    std::vector<Point<2>> initial = initial_vertices;
    auto result = bisect(mesh, initial, size_bound, max_cells, "");
    if (result.n_bisections == 0)
      return result;
    check(mesh);
    check_initial_geometry(mesh, initial);
    initial_vertices.swap(initial);
    install(std::move(mesh));
    return result;
  }



  void
  CrackableMesh::relocate_vertices(
    const std::vector<unsigned int> &moved,
    const std::vector<Point<2>>     &position,
    const std::vector<Point<2>>     &initial_position)
  {
    AssertDimension(moved.size(), position.size());
    AssertDimension(moved.size(), initial_position.size());
    auto &vertices =
      const_cast<std::vector<Point<2>> &>(triangulation->get_vertices());
    for (unsigned int i = 0; i < moved.size(); ++i)
      {
        AssertIndexRange(moved[i], vertices.size());
        vertices[moved[i]]            = position[i];
        block_mesh.vertices[moved[i]] = position[i];
        initial_vertices[moved[i]]    = initial_position[i];
      }
  }



  bool
  CrackableMesh::inverts_a_cell(
    const std::vector<Tensor<1, 2>> &displacement) const
  {
    const auto twice_area = [](const std::array<Point<2>, 3> &p) {
      return (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
             (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    };
    // On deal.II's threads: the answer does not depend on which cell a
    // thread finds first.
    std::atomic<bool> inverted(false);
    parallel::apply_to_subranges(
      std::size_t(0),
      block_mesh.triangles.size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t c = begin; c < end && !inverted; ++c)
          {
            const auto             &t = block_mesh.triangles[c];
            std::array<Point<2>, 3> now, next;
            for (unsigned int k = 0; k < 3; ++k)
              {
                now[k]  = block_mesh.vertices[t[k]];
                next[k] = now[k] + displacement[t[k]];
              }
            if (twice_area(now) * twice_area(next) <= 0)
              inverted = true;
          }
      },
      4096);
    return inverted;
  }



  std::pair<Point<2>, Point<2>>
  CrackableMesh::bounding_box() const
  {
    Point<2> lower = block_mesh.vertices[0], upper = block_mesh.vertices[0];
    for (const auto &v : block_mesh.vertices)
      for (unsigned int d = 0; d < 2; ++d)
        {
          lower[d] = std::min(lower[d], v[d]);
          upper[d] = std::max(upper[d], v[d]);
        }
    return {lower, upper};
  }



  std::pair<unsigned int, Point<2>>
  CrackableMesh::locate(const Point<2> &p) const
  {
    const auto   box = bounding_box();
    const double tolerance =
      1e-10 * std::max(1., box.first.distance(box.second));
    unsigned int best       = numbers::invalid_unsigned_int;
    double       best_score = -tolerance;
    Point<2>     best_unit;
    for (unsigned int c = 0; c < block_mesh.triangles.size(); ++c)
      {
        const auto        &t  = block_mesh.triangles[c];
        const auto        &v  = block_mesh.vertices;
        const Tensor<1, 2> e1 = v[t[1]] - v[t[0]], e2 = v[t[2]] - v[t[0]];
        const Tensor<1, 2> r   = p - v[t[0]];
        const double       det = e1[0] * e2[1] - e1[1] * e2[0];
        // x = v0 + xi e1 + eta e2 (deal.II's reference triangle).
        const double xi  = (r[0] * e2[1] - r[1] * e2[0]) / det;
        const double eta = (e1[0] * r[1] - e1[1] * r[0]) / det;
        // Smallest barycentric coordinate, in units of length.
        const double score =
          std::min({xi, eta, 1. - xi - eta}) * std::sqrt(std::abs(det));
        if (score > best_score)
          {
            best       = c;
            best_score = score;
            best_unit  = Point<2>(xi, eta);
          }
      }
    return {best, best_unit};
  }



  double
  CrackableMesh::area() const
  {
    double sum = 0;
    for (const auto &t : block_mesh.triangles)
      sum += signed_area(block_mesh.vertices, t);
    return sum;
  }
} // namespace ndda
