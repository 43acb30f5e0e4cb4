// SPDX-License-Identifier: GPL-3.0-or-later
//
// Contact detection shared among MPI processes (issue 19), run by ctest on
// two (`mpirun -np 2`): each process keeps a NeighbourList of the vertices
// it owns (OwnedCells::owned_vertices(): the owner of a vertex's first
// cell) over its own and its ghost edges, and OwnedCells::gather() joins
// the processes' candidates.
//
// A scene of 300 small blocks (triangles and turned squares) with its
// cells numbered from left to right, so that each process owns a part of
// the scene, moves at random for 300 steps (mostly small steps, every
// 50th a jump beyond the lists' skin, the threshold changing):
//  - every vertex has exactly one owner;
//  - the gathered candidates equal contact::detect() on the whole scene,
//    field by field, in every step, with a skin and without (the lists'
//    reach then is the threshold itself);
//  - each process's candidates are those of its own vertices;
//  - each process's list holds fewer edges than the scene (its own and
//    its ghosts), and on two processes the scene's contacts are shared
//    between them;
//  - a block thrown across the scene while the others stand still is
//    seen by every process it comes near (candidates equal detect()).

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <ndda/contact/contact_detection.h>
#include <ndda/geometry/block_mesh.h>
#include <ndda/parallel/owned_cells.h>

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
using ndda_tests::check;
using ndda_tests::same_candidates;


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const unsigned int                       n_processes =
    dealii::Utilities::MPI::n_mpi_processes(comm);
  dealii::ConditionalOStream out(
    std::cout, dealii::Utilities::MPI::this_mpi_process(comm) == 0);
  out << "processes: " << (n_processes > 1 ? "several" : "one") << std::endl;

  // 150 triangles and 150 turned squares in [0, 3] x [0, 1], numbered
  // from left to right.
  std::mt19937        random(11);
  geometry::BlockMesh mesh  = ndda_tests::random_blocks(300, 3., random, true);
  const auto          edges = boundary_edges(mesh);
  OwnedCells          cells;
  cells.set_communicator(comm);
  cells.reinit(mesh.triangles.size());
  std::vector<unsigned int> cell_vertices;
  for (const auto &t : mesh.triangles)
    cell_vertices.insert(cell_vertices.end(), t.begin(), t.end());
  const std::vector<bool> owned =
    cells.owned_vertices(cell_vertices, 3, mesh.vertices.size());

  // Every process's candidates, joined and sorted by vertex, then edge.
  const auto joined = [&cells](const std::vector<Candidate> &local) {
    std::vector<Candidate> all = cells.gather(local);
    std::sort(all.begin(),
              all.end(),
              [](const Candidate &a, const Candidate &b) {
                return std::tie(a.vertex, a.edge) < std::tie(b.vertex, b.edge);
              });
    return all;
  };

  // Every vertex has one owner.
  {
    std::vector<unsigned int> count(owned.begin(), owned.end());
    dealii::Utilities::MPI::sum(count, comm, count);
    check(std::all_of(count.begin(),
                      count.end(),
                      [](const unsigned int c) { return c == 1; }),
          "every vertex has one owner");
    out << "vertices: each owned by one process" << std::endl;
  }

  // With a skin (the handler's) and without one.
  for (const double skin : {1., 0.})
    {
      contact::NeighbourList list(skin);
      list.set_owned_vertices(owned);
      geometry::BlockMesh moving = mesh;
      std::mt19937        random(5);
      unsigned int        n_same = 0, n_own = 0, n_steps = 300;
      std::size_t         n_candidates = 0, n_local = 0, local_edges = 0;
      for (unsigned int step = 0; step < n_steps; ++step)
        {
          ndda_tests::move_blocks(moving,
                                  random,
                                  step % 50 == 49 ? 0.05 : 0.001);
          const double                 threshold = 0.01 + 0.01 * (step % 3);
          const std::vector<Candidate> local =
            list.detect(moving.vertices, edges, threshold);
          n_own +=
            std::all_of(local.begin(), local.end(), [&](const Candidate &c) {
              return owned[c.vertex];
            });
          const std::vector<Candidate> whole =
            contact::detect(moving.vertices, edges, threshold);
          n_same += same_candidates(joined(local), whole);
          n_candidates += whole.size();
          n_local += local.size();
          local_edges = std::max(local_edges, list.n_local_edges());
        }
      n_same                       = dealii::Utilities::MPI::min(n_same, comm);
      n_own                        = dealii::Utilities::MPI::min(n_own, comm);
      const std::size_t most_local = dealii::Utilities::MPI::max(n_local, comm);
      const std::size_t most_local_edges =
        dealii::Utilities::MPI::max(local_edges, comm);
      std::cerr << "skin " << skin << ", process "
                << dealii::Utilities::MPI::this_mpi_process(comm) << ": "
                << n_local << " of " << n_candidates << " candidates, at most "
                << local_edges << " of " << edges.size() << " edges, "
                << list.n_builds() << " builds" << std::endl;
      out << "skin " << skin << ": gathered candidates equal detect() in "
          << n_same << " of " << n_steps << " steps" << std::endl;
      check(n_same == n_steps, "the gathered candidates are detect()'s");
      check(n_own == n_steps, "a process's candidates are its own vertices'");
      check(n_candidates > 10 * n_steps, "the scene has contacts");
      if (n_processes > 1)
        {
          check(most_local_edges < edges.size(),
                "a process holds fewer edges than the scene");
          check(most_local < n_candidates,
                "the candidates are shared among the processes");
          out << "skin " << skin
              << ": each process holds part of the edges and of the "
                 "candidates"
              << std::endl;
        }
    }
  // A block thrown from one end of the scene to the other while the rest
  // stands still: the processes it comes near must see it although none of
  // their own or ghost edges moves.
  {
    contact::NeighbourList list;
    list.set_owned_vertices(owned);
    geometry::BlockMesh       moving = mesh;
    const unsigned int        thrown = moving.block_names.size() - 1;
    std::vector<unsigned int> nodes;
    for (unsigned int c = 0; c < moving.triangles.size(); ++c)
      if (moving.cell_block[c] == thrown)
        nodes.insert(nodes.end(),
                     moving.triangles[c].begin(),
                     moving.triangles[c].end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const double       threshold = 0.01;
    const unsigned int n_steps   = 750;
    unsigned int       n_same    = 0;
    std::size_t        n_thrown  = 0;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        for (const unsigned int v : nodes)
          moving.vertices[v][0] -= 0.004;
        const std::vector<Candidate> whole =
          contact::detect(moving.vertices, edges, threshold);
        n_same += same_candidates(
          joined(list.detect(moving.vertices, edges, threshold)), whole);
        for (const Candidate &c : whole)
          n_thrown += (edges[c.edge].block == thrown) !=
                      std::binary_search(nodes.begin(), nodes.end(), c.vertex);
      }
    n_same = dealii::Utilities::MPI::min(n_same, comm);
    out << "thrown block: gathered candidates equal detect() in " << n_same
        << " of " << n_steps << " steps" << std::endl;
    check(n_same == n_steps, "the thrown block is seen");
    check(n_thrown > 100, "the thrown block meets others");
  }
  out << "OK" << std::endl;
  return 0;
}
