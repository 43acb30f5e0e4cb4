// SPDX-License-Identifier: GPL-3.0-or-later
//
// Contact detection (broad and narrow phase) on hand-made meshes:
//  1. two unit squares side by side with a gap, aligned and shifted;
//  2. two unit squares corner to corner;
//  3. a block with a crack (split_vertices_along_edges): the crack faces
//     find each other, adjacent edges never do;
//  4. a random scene of small blocks: detect() against an O(n^2) loop over
//     all pairs of boundary edges;
//  5. the same scene in random motion (every block translated and turned
//     by a random amount each step, some steps far beyond the list's skin,
//     the threshold changing): a NeighbourList gives detect()'s candidates
//     in every step, and rebuilds only when it must.

#include <ndda/contact/contact_detection.h>
#include <ndda/geometry/block_mesh.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <tuple>
#include <vector>

#include "grids.h"
#include "tests.h"

using namespace ndda;
using contact::Candidate;
using contact::CandidateType;
using dealii::Point;
using ndda_tests::check;
using ndda_tests::same_candidates;

namespace
{
  /** Append the square [x, x+side] x [y, y+side] as a block of 2 triangles. */
  void
  add_square(geometry::BlockMesh &mesh,
             const double         x,
             const double         y,
             const double         side = 1.)
  {
    const unsigned int n     = mesh.vertices.size();
    const unsigned int block = mesh.block_names.size();
    mesh.vertices.emplace_back(x, y);
    mesh.vertices.emplace_back(x + side, y);
    mesh.vertices.emplace_back(x + side, y + side);
    mesh.vertices.emplace_back(x, y + side);
    mesh.triangles.push_back({{n, n + 1, n + 2}});
    mesh.triangles.push_back({{n, n + 2, n + 3}});
    mesh.cell_block.insert(mesh.cell_block.end(), 2, block);
    mesh.cell_material.insert(mesh.cell_material.end(), 2, 0);
    mesh.block_names.push_back("square" + std::to_string(block));
  }


  std::vector<Candidate>
  detect(const geometry::BlockMesh &mesh, const double threshold)
  {
    return contact::detect(mesh.vertices, boundary_edges(mesh), threshold);
  }


  unsigned int
  count(const std::vector<Candidate> &candidates, const CandidateType type)
  {
    return std::count_if(candidates.begin(),
                         candidates.end(),
                         [type](const Candidate &c) { return c.type == type; });
  }


  void
  print(const std::vector<Candidate>    &candidates,
        const std::vector<BoundaryEdge> &edges)
  {
    for (const Candidate &c : candidates)
      std::cout << "    vertex " << c.vertex << " edge " << c.edge << " ("
                << edges[c.edge].v0 << "->" << edges[c.edge].v1 << ", block "
                << edges[c.edge].block << ") "
                << (c.type == CandidateType::vertex_edge ? "vertex-edge  " :
                                                           "vertex-vertex")
                << " distance " << c.distance << " ratio " << c.edge_ratio
                << std::endl;
  }


  void
  test_side_by_side()
  {
    std::cout << "1. two unit squares side by side, gap 0.01" << std::endl;
    const double gap = 0.01;

    // Aligned: every facing vertex projects onto an end point of the facing
    // edge (and of the other square's top or bottom edge), so all
    // candidates are vertex-vertex.
    {
      geometry::BlockMesh mesh;
      add_square(mesh, 0., 0.);
      add_square(mesh, 1. + gap, 0.);
      const auto edges = boundary_edges(mesh);
      check(edges.size() == 8, "two squares have 8 boundary edges");
      const auto candidates = detect(mesh, 0.02);
      std::cout << "  aligned, threshold 0.02: " << candidates.size()
                << " candidates, "
                << count(candidates, CandidateType::vertex_edge)
                << " vertex-edge" << std::endl;
      print(candidates, edges);
      check(candidates.size() == 8, "aligned: 8 candidates");
      for (const Candidate &c : candidates)
        {
          check(std::abs(c.distance - gap) < 1e-12, "aligned: distance gap");
          check(c.type == CandidateType::vertex_vertex,
                "aligned: vertex-vertex");
          check(edges[c.edge].block != (c.vertex < 4 ? 0u : 1u),
                "aligned: vertex against the other square");
        }
      // The four facing vertices each see the facing edge.
      for (const unsigned int v : {1u, 2u, 4u, 7u})
        check(std::count_if(candidates.begin(),
                            candidates.end(),
                            [&](const Candidate &c) {
                              const auto &e = edges[c.edge];
                              return c.vertex == v &&
                                     (e.v0 == (v < 4 ? 7u : 1u) ||
                                      e.v0 == (v < 4 ? 4u : 2u)) &&
                                     std::abs(mesh.vertices[e.v0][0] -
                                              mesh.vertices[e.v1][0]) < 1e-12;
                            }) == 1,
              "aligned: facing vertex against facing edge");
      const auto none = detect(mesh, 0.005);
      std::cout << "  aligned, threshold 0.005: " << none.size()
                << " candidates" << std::endl;
      check(none.empty(), "aligned: none below the gap");
    }

    // Shifted by half a side: one vertex of each square projects into the
    // middle of the other's facing edge.
    {
      geometry::BlockMesh mesh;
      add_square(mesh, 0., 0.);
      add_square(mesh, 1. + gap, 0.5);
      const auto edges      = boundary_edges(mesh);
      const auto candidates = detect(mesh, 0.02);
      std::cout << "  shifted by 0.5, threshold 0.02: " << candidates.size()
                << " candidates, "
                << count(candidates, CandidateType::vertex_edge)
                << " vertex-edge" << std::endl;
      print(candidates, edges);
      check(candidates.size() == 2, "shifted: 2 candidates");
      for (const Candidate &c : candidates)
        {
          check(c.type == CandidateType::vertex_edge, "shifted: vertex-edge");
          check(std::abs(c.distance - gap) < 1e-12, "shifted: distance gap");
          check(std::abs(c.edge_ratio - 0.5) < 1e-12, "shifted: ratio 0.5");
        }
      check(detect(mesh, 0.005).empty(), "shifted: none below the gap");

      // Penetration: the second square moved into the first one.
      mesh.vertices[4][0] = mesh.vertices[7][0] = 1. - gap;
      mesh.vertices[5][0] = mesh.vertices[6][0] = 2. - gap;
      const auto pen                            = detect(mesh, 0.02);
      std::cout << "  penetrating by 0.01: " << pen.size()
                << " candidates, distances";
      for (const Candidate &c : pen)
        std::cout << ' ' << c.distance;
      std::cout << std::endl;
      bool found = false;
      for (const Candidate &c : pen)
        if (c.vertex == 4 && c.type == CandidateType::vertex_edge)
          {
            found = true;
            check(std::abs(c.distance + gap) < 1e-12,
                  "penetration: negative distance");
          }
      check(found, "penetration: vertex 4 against the first square");
    }
  }


  void
  test_corner_to_corner()
  {
    std::cout << "2. two unit squares corner to corner, gap 0.01 along the "
                 "diagonal"
              << std::endl;
    const double        gap = 0.01;
    const double        d   = gap / std::sqrt(2.);
    geometry::BlockMesh mesh;
    add_square(mesh, 0., 0.);
    add_square(mesh, 1. + d, 1. + d);
    const auto edges      = boundary_edges(mesh);
    const auto candidates = detect(mesh, 0.02);
    std::cout << "  threshold 0.02: " << candidates.size() << " candidates, "
              << count(candidates, CandidateType::vertex_vertex)
              << " vertex-vertex" << std::endl;
    print(candidates, edges);
    check(candidates.size() == 4, "corner: 4 candidates");
    for (const Candidate &c : candidates)
      {
        check(c.type == CandidateType::vertex_vertex, "corner: vertex-vertex");
        check(c.vertex == 2 || c.vertex == 4, "corner: only the corners");
        check(std::abs(c.distance - gap) < 1e-12, "corner: distance");
      }
    check(detect(mesh, 0.009).empty(), "corner: none below the gap");
  }


  void
  test_crack()
  {
    std::cout << "3. one block, 4x2 cells, crack from the left side to the "
                 "middle"
              << std::endl;
    // Vertices (i, j), i = 0..4, j = 0..2, index i + 5 j; each unit cell
    // split into two counter-clockwise triangles.
    geometry::BlockMesh mesh;
    for (unsigned int j = 0; j <= 2; ++j)
      for (unsigned int i = 0; i <= 4; ++i)
        mesh.vertices.emplace_back(i, j);
    for (unsigned int j = 0; j < 2; ++j)
      for (unsigned int i = 0; i < 4; ++i)
        {
          const unsigned int v = i + 5 * j;
          mesh.triangles.push_back({{v, v + 1, v + 6}});
          mesh.triangles.push_back({{v, v + 6, v + 5}});
        }
    mesh.cell_block.assign(mesh.triangles.size(), 0);
    mesh.cell_material.assign(mesh.triangles.size(), 0);
    mesh.block_names = {"block"};

    const double threshold = 0.4;
    {
      const auto edges      = boundary_edges(mesh);
      const auto candidates = detect(mesh, threshold);
      std::cout << "  before splitting: " << edges.size() << " boundary edges, "
                << candidates.size() << " candidates" << std::endl;
      check(edges.size() == 12, "uncracked: 12 boundary edges");
      check(candidates.empty(), "uncracked: adjacent edges give nothing");
    }

    // Crack along y = 1 from (0,1) to the tip (2,1).
    const auto origin =
      geometry::split_vertices_along_edges(mesh, {{{5, 6}}, {{6, 7}}});
    const auto edges      = boundary_edges(mesh);
    const auto candidates = detect(mesh, threshold);
    std::cout << "  after splitting: " << mesh.vertices.size() << " vertices, "
              << edges.size() << " boundary edges, " << candidates.size()
              << " candidates, "
              << count(candidates, CandidateType::vertex_vertex)
              << " vertex-vertex" << std::endl;
    print(candidates, edges);
    check(edges.size() == 16, "cracked: 16 boundary edges");

    // Every candidate: same block, distance 0, the vertex sits on an end
    // point of the edge without being that end point, and the vertex is a
    // copy of a split vertex ((0,1) or (1,1)).
    for (const Candidate &c : candidates)
      {
        const auto &e = edges[c.edge];
        check(e.block == 0, "cracked: same block");
        check(std::abs(c.distance) < 1e-12, "cracked: distance 0");
        check(c.vertex != e.v0 && c.vertex != e.v1,
              "cracked: vertex not on its own edge");
        check(c.type == CandidateType::vertex_vertex,
              "cracked: coincident vertices are vertex-vertex");
        check(origin[c.vertex] == 5 || origin[c.vertex] == 6,
              "cracked: only the split vertices");
      }
    // Each copy of (1,1) sees the two edges of the opposite crack face that
    // end at its twin; each copy of (0,1) sees the opposite crack face's
    // edge and the outer edge below or above it.
    check(candidates.size() == 8, "cracked: 8 candidates");
    // The two crack faces detect each other.
    unsigned int crack_face_pairs = 0;
    for (const Candidate &c : candidates)
      {
        const auto &e = edges[c.edge];
        if (mesh.vertices[e.v0][1] == 1. && mesh.vertices[e.v1][1] == 1.)
          ++crack_face_pairs;
      }
    std::cout << "  candidates against crack faces: " << crack_face_pairs
              << std::endl;
    check(crack_face_pairs == 6, "cracked: 6 candidates on crack faces");
  }


  void
  test_meshed_crack()
  {
    std::cout << "3b. mesh_scene: block [0,4]x[0,2] with an interior crack "
                 "from (1,1) to (3,1)"
              << std::endl;
    geometry::SceneGeometry    scene;
    geometry::BlockDescription block;
    block.name      = "cracked";
    block.outer     = {Point<2>(0, 0),
                       Point<2>(4, 0),
                       Point<2>(4, 2),
                       Point<2>(0, 2)};
    block.cracks    = {{Point<2>(1, 1), Point<2>(3, 1)}};
    block.mesh_size = 0.5;
    scene.blocks.push_back(block);
    const auto mesh  = geometry::mesh_scene(scene);
    const auto edges = boundary_edges(mesh);

    const double threshold  = 0.05;
    const auto   candidates = detect(mesh, threshold);
    const auto   on_crack   = [&](const Point<2> &p) {
      return std::abs(p[1] - 1.) < 1e-12 && p[0] > 1. - 1e-12 &&
             p[0] < 3. + 1e-12;
    };
    unsigned int n_crack_edges = 0;
    for (const auto &e : edges)
      if (on_crack(mesh.vertices[e.v0]) && on_crack(mesh.vertices[e.v1]))
        ++n_crack_edges;
    std::cout << "  " << mesh.triangles.size() << " triangles, " << edges.size()
              << " boundary edges (" << n_crack_edges
              << " on the crack faces), " << candidates.size()
              << " candidates, "
              << count(candidates, CandidateType::vertex_vertex)
              << " vertex-vertex" << std::endl;
    check(n_crack_edges >= 4, "meshed crack: both faces are boundary");
    check(!candidates.empty(), "meshed crack: the faces see each other");
    for (const Candidate &c : candidates)
      {
        const auto &e = edges[c.edge];
        check(on_crack(mesh.vertices[c.vertex]) &&
                on_crack(mesh.vertices[e.v0]) && on_crack(mesh.vertices[e.v1]),
              "meshed crack: only crack faces, never adjacent outer edges");
        check(std::abs(c.distance) < 1e-12, "meshed crack: distance 0");
        check(c.vertex != e.v0 && c.vertex != e.v1,
              "meshed crack: vertex not on its own edge");
      }
    // Every split vertex (not the tips) has a twin across the crack.
    std::vector<bool> has_candidate(mesh.vertices.size(), false);
    for (const Candidate &c : candidates)
      has_candidate[c.vertex] = true;
    unsigned int n_split = 0;
    for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
      if (on_crack(mesh.vertices[v]) &&
          mesh.vertices[v].distance(Point<2>(1, 1)) > 1e-12 &&
          mesh.vertices[v].distance(Point<2>(3, 1)) > 1e-12)
        {
          ++n_split;
          check(has_candidate[v], "meshed crack: split vertex detected");
        }
    std::cout << "  split crack vertices with a candidate: " << n_split
              << std::endl;
  }


  /** detect() by an O(n^2) loop over all pairs of edges. */
  std::vector<Candidate>
  brute_force(const std::vector<Point<2>>     &vertices,
              const std::vector<BoundaryEdge> &edges,
              const double                     threshold)
  {
    std::vector<Candidate> result;
    Candidate              c;
    for (unsigned int i = 0; i < edges.size(); ++i)
      for (unsigned int j = 0; j < edges.size(); ++j)
        {
          const auto &a = edges[i];
          const auto &b = edges[j];
          if (i == j || a.v0 == b.v0 || a.v0 == b.v1 || a.v1 == b.v0 ||
              a.v1 == b.v1)
            continue;
          for (const unsigned int v : {b.v0, b.v1})
            if (contact::vertex_edge_candidate(
                  vertices, v, edges, i, threshold, c))
              result.push_back(c);
        }
    std::sort(result.begin(),
              result.end(),
              [](const Candidate &a, const Candidate &b) {
                return std::tie(a.vertex, a.edge) < std::tie(b.vertex, b.edge);
              });
    result.erase(std::unique(result.begin(),
                             result.end(),
                             [](const Candidate &a, const Candidate &b) {
                               return a.vertex == b.vertex && a.edge == b.edge;
                             }),
                 result.end());
    return result;
  }


  /** 100 triangles and 100 rotated squares in the unit square. */
  geometry::BlockMesh
  random_scene()
  {
    std::mt19937 random(42);
    return ndda_tests::random_blocks(200, 1., random);
  }



  void
  test_random_scene()
  {
    std::cout << "4. random scene: 100 triangles and 100 rotated squares in "
                 "the unit square"
              << std::endl;
    const geometry::BlockMesh mesh  = random_scene();
    const auto                edges = boundary_edges(mesh);
    check(edges.size() == 100 * 3 + 100 * 4, "random: 700 boundary edges");
    for (const double threshold : {0., 0.005, 0.02, 0.1})
      {
        const auto fast = contact::detect(mesh.vertices, edges, threshold);
        const auto slow = brute_force(mesh.vertices, edges, threshold);
        const bool same = same_candidates(fast, slow);
        std::cout << "  threshold " << threshold << ": detect " << fast.size()
                  << " candidates ("
                  << count(fast, CandidateType::vertex_vertex)
                  << " vertex-vertex), brute force " << slow.size() << ", "
                  << (same ? "identical" : "DIFFERENT") << std::endl;
        check(same, "random: detect equals brute force");
        if (threshold >= 0.02)
          check(!fast.empty(), "random: the scene has contacts");
      }
  }


  void
  test_neighbour_list()
  {
    std::cout << "5. the random scene in motion, 400 steps: NeighbourList "
                 "against detect()"
              << std::endl;
    geometry::BlockMesh                    mesh  = random_scene();
    const auto                             edges = boundary_edges(mesh);
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> unit(-1., 1.);
    contact::NeighbourList                 list;
    unsigned int       n_same = 0, n_candidates = 0, n_jumps = 0;
    const unsigned int n_steps = 400;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        // Every block moves by a random increment: mostly small against the
        // threshold, every 50th step a jump of several thresholds.
        const double threshold = 0.01 + 0.01 * (step % 3);
        const double scale     = (step % 50 == 49 ? 0.05 : 0.001);
        n_jumps += (step % 50 == 49);
        ndda_tests::move_blocks(mesh, random, scale);
        const auto cached = list.detect(mesh.vertices, edges, threshold);
        const auto fresh  = contact::detect(mesh.vertices, edges, threshold);
        n_same += same_candidates(cached, fresh);
        n_candidates += fresh.size();
      }
    std::cout << "  identical in " << n_same << " of " << n_steps << " steps ("
              << n_candidates << " candidates in all), " << list.n_builds()
              << " builds of the list" << std::endl;
    check(n_same == n_steps, "neighbour list: detect()'s candidates");
    check(n_candidates > 10 * n_steps,
          "neighbour list: the scene has contacts");
    check(list.n_builds() > n_jumps, "neighbour list: rebuilt after jumps");
    check(list.n_builds() < n_steps / 4, "neighbour list: reused");
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  test_side_by_side();
  test_corner_to_corner();
  test_crack();
  test_meshed_crack();
  test_random_scene();
  test_neighbour_list();
  std::cout << "OK" << std::endl;
  return 0;
}
