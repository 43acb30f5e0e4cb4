// SPDX-License-Identifier: GPL-3.0-or-later
//
// Unit test of local refinement by longest-edge bisection
// (CrackableMesh::refine(), mesh/refinement.h) and of carrying state to
// the refined mesh (state_transfer::transfer_refined()). The mesh: an
// 8 x 8 grid of unit squares cut by their diagonals (block 0), cracked
// along y = 4 from x = 1 to x = 4 (tip at (4, 4)), with one more
// diagonal marked as a closed crack, and a 2 x 2 grid beside it (block 1).
// Refined near the tip to h = 0.1 growing with g = 1.3, in block 0 only.
//
// Asserted:
//  1. the refined mesh passes CrackableMesh::check() in both geometries
//     (done by refine()), it is conforming: the edges with one triangle
//     have the same total length as before (a hanging node would add an
//     edge of one triangle inside the block), and the area is kept to
//     1e-14 in the present and the initial geometry;
//  2. every cell of block 0 meets the size bound; the smallest angle is
//     at least half the smallest angle before (Rivara's bound); block 1 is
//     unchanged; the crack faces are bisected in pairs: every face is a
//     side of a triangle, every open face has a copy with the same
//     initial ends, and their total length is kept;
//  3. every new cell's vertices are its origin cell's at the recorded
//     reference points, in both geometries (to 1e-12);
//  4. more cells than the limit: an ExcMessage, the mesh unchanged;
//  5. crack() with a RefineAfterCrack makes, in one rebuild, the mesh that
//     crack() and then refine() make (same cells, vertices, crack faces,
//     origins); beyond the limit the crack is refused too, and the error
//     names the refinement;
//  6. transfer_refined() carries the element's own fields exactly (P1
//     linear, P2 quadratic, two components) and a stress linear in space
//     through the degree 1 fit (three Gauss points); degree 0 gives the
//     old cell's mean.

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools_interpolate.h>

#include <ndda/mesh/crackable_mesh.h>
#include <ndda/mesh/state_transfer.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>

#include "grids.h"
#include "tests.h"

using namespace ndda;
using dealii::Point;
using ndda_tests::check;
using ndda_tests::Field;
using ndda_tests::unit_grid;
using ndda_tests::vertex_at;

namespace
{
  constexpr double tip_size = 0.1, growth = 1.3;
  const Point<2>   tip(4, 4);

  /** Block 0 (8 x 8) and block 1 (2 x 2, at x = 10). */
  geometry::BlockMesh
  two_blocks()
  {
    auto               mesh   = unit_grid(8);
    const auto         other  = unit_grid(2, 10, 0, 1);
    const unsigned int offset = mesh.vertices.size();
    mesh.vertices.insert(mesh.vertices.end(),
                         other.vertices.begin(),
                         other.vertices.end());
    for (auto t : other.triangles)
      {
        for (auto &v : t)
          v += offset;
        mesh.triangles.push_back(t);
        mesh.cell_block.push_back(1);
        mesh.cell_material.push_back(0);
      }
    mesh.block_names = {"left", "right"};
    return mesh;
  }

  /** The cracked and marked mesh, ready to refine (or refined in the same
   * rebuild, with @p refine). */
  CrackResult
  make_mesh(CrackableMesh &mesh, const RefineAfterCrack &refine = {})
  {
    mesh.build(two_blocks());
    std::vector<std::array<unsigned int, 2>> edges;
    for (unsigned int i = 1; i < 4; ++i)
      edges.push_back({{vertex_at(mesh, Point<2>(i, 4)),
                        vertex_at(mesh, Point<2>(i + 1, 4))}});
    // A diagonal with both ends inside the block: a closed crack.
    edges.push_back(
      {{vertex_at(mesh, Point<2>(5, 1)), vertex_at(mesh, Point<2>(6, 2))}});
    return mesh.crack(edges, refine);
  }

  double
  size_bound(const unsigned int block, const Point<2> &x)
  {
    return block == 0 ? tip_size + (growth - 1) * x.distance(tip) :
                        std::numeric_limits<double>::infinity();
  }

  double
  twice_area(const std::vector<Point<2>> &x, const std::array<unsigned, 3> &t)
  {
    return (x[t[1]][0] - x[t[0]][0]) * (x[t[2]][1] - x[t[0]][1]) -
           (x[t[1]][1] - x[t[0]][1]) * (x[t[2]][0] - x[t[0]][0]);
  }

  double
  area(const std::vector<Point<2>>                    &x,
       const std::vector<std::array<unsigned int, 3>> &triangles)
  {
    double sum = 0;
    for (const auto &t : triangles)
      sum += 0.5 * twice_area(x, t);
    return sum;
  }

  /** Total length of the edges that only one triangle has. */
  double
  single_edge_length(const geometry::BlockMesh &mesh)
  {
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> count;
    for (const auto &t : mesh.triangles)
      for (unsigned int i = 0; i < 3; ++i)
        ++count[std::minmax(t[i], t[(i + 1) % 3])];
    double length = 0;
    for (const auto &[edge, n] : count)
      if (n == 1)
        length +=
          mesh.vertices[edge.first].distance(mesh.vertices[edge.second]);
    return length;
  }

  double
  smallest_angle(const geometry::BlockMesh &mesh)
  {
    double smallest = M_PI;
    for (const auto &t : mesh.triangles)
      for (unsigned int i = 0; i < 3; ++i)
        {
          const auto a = mesh.vertices[t[(i + 1) % 3]] - mesh.vertices[t[i]];
          const auto b = mesh.vertices[t[(i + 2) % 3]] - mesh.vertices[t[i]];
          smallest =
            std::min(smallest, std::acos(a * b / (a.norm() * b.norm())));
        }
    return smallest;
  }

  double
  longest_edge(const geometry::BlockMesh &mesh, const unsigned int c)
  {
    const auto &t = mesh.triangles[c];
    const auto &x = mesh.vertices;
    return std::max({x[t[0]].distance(x[t[1]]),
                     x[t[1]].distance(x[t[2]]),
                     x[t[2]].distance(x[t[0]])});
  }

  Point<2>
  at(const std::vector<Point<2>>       &x,
     const std::array<unsigned int, 3> &t,
     const Point<2>                    &xi)
  {
    return Point<2>(x[t[0]] + xi[0] * (x[t[1]] - x[t[0]]) +
                    xi[1] * (x[t[2]] - x[t[0]]));
  }

  /** A field of two components the element @p degree holds exactly. */
  std::vector<dealii::types::global_dof_index>
  cell_dofs(const dealii::DoFHandler<2> &dofs)
  {
    std::vector<dealii::types::global_dof_index> all, local;
    local.resize(dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        all.insert(all.end(), local.begin(), local.end());
      }
    return all;
  }

  /** 5: fields and stresses carried to the refined mesh. */
  void
  check_transfer(const unsigned int degree)
  {
    CrackableMesh mesh;
    make_mesh(mesh);
    const dealii::FESystem<2>  fe(dealii::FE_SimplexP<2>(degree), 2);
    const dealii::MappingFE<2> mapping(dealii::FE_SimplexP<2>(1));
    dealii::DoFHandler<2>      dofs(mesh.get_triangulation());
    dofs.distribute_dofs(fe);
    const auto             old_cell_dofs = cell_dofs(dofs);
    dealii::Vector<double> u_old(dofs.n_dofs());
    dealii::VectorTools::interpolate(mapping, dofs, Field(degree), u_old);

    // A stress linear in space at the points of the cell quadrature.
    const dealii::QGaussSimplex<2> quadrature(degree);
    const auto                     stress = [](const Point<2> &x) {
      dealii::SymmetricTensor<2, 2> s;
      s[0][0] = 1 + x[0];
      s[1][1] = 2 - 3 * x[1];
      s[0][1] = 0.5 * x[0] - x[1];
      return s;
    };
    const auto old_mesh = mesh.get_block_mesh();
    std::vector<std::vector<dealii::SymmetricTensor<2, 2>>> values;
    for (const auto &t : old_mesh.triangles)
      {
        values.emplace_back();
        for (const auto &q : quadrature.get_points())
          values.back().push_back(stress(at(old_mesh.vertices, t, q)));
      }

    const auto refined = mesh.refine(size_bound, 100000);
    dofs.distribute_dofs(fe);
    const auto             new_cell_dofs = cell_dofs(dofs);
    dealii::Vector<double> u(dofs.n_dofs()), exact(dofs.n_dofs());
    state_transfer::transfer_refined(
      fe, old_cell_dofs, refined, new_cell_dofs, {&u_old}, {&u});
    dealii::VectorTools::interpolate(mapping, dofs, Field(degree), exact);
    exact -= u;
    std::cout << "P" << degree << ": " << refined.n_bisections
              << " bisections, field error " << exact.linfty_norm();
    check(exact.linfty_norm() < 1e-12,
          "the element's own field is carried exactly");

    state_transfer::transfer_refined(quadrature, degree - 1, refined, values);
    const auto &mesh_now = mesh.get_block_mesh();
    double      error    = 0;
    for (unsigned int c = 0; c < mesh_now.triangles.size(); ++c)
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          // Degree 0: the mean of the old cell (its one point's value).
          const unsigned int p = refined.cell_origin[c];
          const auto         x =
            degree == 1 ?
                      at(old_mesh.vertices,
                 old_mesh.triangles[p],
                 quadrature.point(q)) :
                      at(mesh_now.vertices, mesh_now.triangles[c], quadrature.point(q));
          error = std::max(error, (values[c][q] - stress(x)).norm());
        }
    std::cout << ", stress error " << error << std::endl;
    check(error < 1e-12, "the stresses are carried by the fit");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  CrackableMesh mesh;
  make_mesh(mesh);
  const auto   before         = mesh.get_block_mesh();
  const auto   initial_before = mesh.get_initial_vertices();
  const double angle_before   = smallest_angle(before);
  const double single_before  = single_edge_length(before);

  const auto  refined = mesh.refine(size_bound, 100000);
  const auto &after   = mesh.get_block_mesh();
  std::cout << "cells " << before.triangles.size() << " -> "
            << after.triangles.size() << ", vertices " << before.vertices.size()
            << " -> " << after.vertices.size() << ", bisections "
            << refined.n_bisections << std::endl;
  check(refined.n_bisections > 100 &&
          after.triangles.size() ==
            before.triangles.size() + refined.n_bisections,
        "each bisection adds one cell");

  // 1. Conforming, same area.
  const double single_after = single_edge_length(after);
  const double area_change =
    std::abs(area(after.vertices, after.triangles) /
               area(before.vertices, before.triangles) -
             1);
  const double initial_area_change =
    std::abs(area(mesh.get_initial_vertices(), after.triangles) /
               area(initial_before, before.triangles) -
             1);
  std::cout << "edges of one triangle: " << single_before << " -> "
            << single_after << "; area change " << area_change << ", initial "
            << initial_area_change << std::endl;
  check(std::abs(single_after - single_before) < 1e-12 * single_before,
        "no hanging node: the edges of one triangle are the same length");
  check(area_change < 1e-14 && initial_area_change < 1e-14, "the area is kept");

  // 2. Sizes, angles, what stays.
  unsigned int n_large       = 0;
  double       smallest_cell = 1e9;
  for (unsigned int c = 0; c < after.triangles.size(); ++c)
    {
      const auto    &t = after.triangles[c];
      const Point<2> centroid(
        (after.vertices[t[0]] + after.vertices[t[1]] + after.vertices[t[2]]) /
        3.);
      smallest_cell = std::min(smallest_cell, longest_edge(after, c));
      if (longest_edge(after, c) >
          size_bound(after.cell_block[c], centroid) * (1 + 1e-12))
        ++n_large;
    }
  std::cout << "cells above the bound " << n_large << ", smallest "
            << smallest_cell << ", smallest angle "
            << smallest_angle(after) * 180 / M_PI << " (before "
            << angle_before * 180 / M_PI << ")" << std::endl;
  check(n_large == 0, "every cell meets the bound");
  check(smallest_cell < 1.5 * tip_size, "the cells at the tip are small");
  check(smallest_angle(after) >= 0.5 * angle_before - 1e-12,
        "the smallest angle is at least half of what it was");
  for (unsigned int c = 0; c < before.triangles.size(); ++c)
    if (before.cell_block[c] == 1)
      check(after.triangles[c] == before.triangles[c] && !refined.is_part[c],
            "block 1 is not refined");
  const auto face_length = [](const geometry::BlockMesh   &m,
                              const std::vector<Point<2>> &x) {
    double length = 0;
    for (const auto &e : m.crack_edges)
      length += x[e[0]].distance(x[e[1]]);
    return length;
  };
  std::cout << "crack faces " << before.crack_edges.size() << " -> "
            << after.crack_edges.size() << std::endl;
  check(after.crack_edges.size() > before.crack_edges.size() &&
          std::abs(face_length(after, after.vertices) -
                   face_length(before, before.vertices)) < 1e-12,
        "crack faces are bisected, their length kept");
  std::map<std::pair<unsigned int, unsigned int>, unsigned int> n_cells_on;
  for (const auto &t : after.triangles)
    for (unsigned int i = 0; i < 3; ++i)
      ++n_cells_on[std::minmax(t[i], t[(i + 1) % 3])];
  const auto &x0 = mesh.get_initial_vertices();
  for (const auto &e : after.crack_edges)
    {
      const auto key = std::minmax(e[0], e[1]);
      check(n_cells_on.count(key) == 1,
            "every crack face is a side of a triangle");
      if (n_cells_on[key] == 2)
        continue;
      unsigned int n_copies = 0;
      for (const auto &f : after.crack_edges)
        if (std::minmax(f[0], f[1]) != key &&
            ((x0[f[0]] == x0[e[0]] && x0[f[1]] == x0[e[1]]) ||
             (x0[f[0]] == x0[e[1]] && x0[f[1]] == x0[e[0]])))
          ++n_copies;
      check(n_copies == 1, "every open crack face has one copy");
    }

  // 3. Origins.
  double origin_error = 0;
  for (unsigned int c = 0; c < after.triangles.size(); ++c)
    {
      const auto &parent = before.triangles[refined.cell_origin[c]];
      for (unsigned int k = 0; k < 3; ++k)
        {
          const auto &xi = refined.reference_vertices[c][k];
          const auto  v  = after.triangles[c][k];
          origin_error   = std::max(
            {origin_error,
               after.vertices[v].distance(at(before.vertices, parent, xi)),
               mesh.get_initial_vertices()[v].distance(
               at(initial_before, parent, xi))});
        }
      check(after.cell_block[c] == before.cell_block[refined.cell_origin[c]],
            "a part stays in its cell's block");
    }
  std::cout << "origin error " << origin_error << std::endl;
  check(origin_error < 1e-12, "every part lies in its origin cell");

  // 4. The limit.
  const unsigned int n_cells = after.triangles.size();
  bool               thrown  = false;
  try
    {
      mesh.refine([](unsigned int, const Point<2> &) { return 0.01; },
                  n_cells + 10);
    }
  catch (const dealii::ExceptionBase &)
    {
      thrown = true;
    }
  check(thrown && mesh.get_block_mesh().triangles.size() == n_cells,
        "a refinement beyond the limit is refused, the mesh unchanged");

  // 5. Crack and refine in one rebuild (RefineAfterCrack): the same mesh
  // as crack() and then refine(); beyond the limit, neither happens.
  {
    RefineAfterCrack refine;
    unsigned int     n_bound_calls = 0;
    refine.size_bound              = [&](const geometry::BlockMesh   &cracked,
                            const std::vector<Point<2>> &initial) {
      ++n_bound_calls;
      check(cracked.crack_edges.size() == before.crack_edges.size() &&
              initial.size() == cracked.vertices.size(),
            "the size bound is made from the cracked mesh");
      return RefineAfterCrack::SizeBound(size_bound);
    };
    refine.max_cells = 100000;
    CrackableMesh     at_once;
    const CrackResult result = make_mesh(at_once, refine);
    const auto       &once   = at_once.get_block_mesh();
    check(n_bound_calls == 1 && result.refined &&
            result.refined->n_bisections == refined.n_bisections &&
            result.refined->cell_origin == refined.cell_origin &&
            once.triangles == after.triangles &&
            once.vertices == after.vertices &&
            once.crack_edges == after.crack_edges &&
            at_once.get_initial_vertices() == mesh.get_initial_vertices() &&
            at_once.get_triangulation().n_active_cells() ==
              after.triangles.size(),
          "crack with refinement makes the mesh of crack, then refine");

    refine.max_cells = before.triangles.size() + 10;
    refine.what      = "the test's refinement";
    CrackableMesh refused;
    refused.build(two_blocks());
    const auto uncracked = refused.get_block_mesh();
    bool       named     = false;
    try
      {
        make_mesh(refused, refine);
      }
    catch (const dealii::ExceptionBase &exc)
      {
        named = std::string(exc.what()).find("the test's refinement") !=
                std::string::npos;
      }
    check(named && refused.get_block_mesh().triangles == uncracked.triangles &&
            refused.get_block_mesh().crack_edges.empty(),
          "a crack whose refinement goes beyond the limit is refused whole, "
          "the error naming the refinement");
    std::cout << "crack and refine in one rebuild: "
              << result.refined->n_bisections << " bisections, same mesh"
              << std::endl;
  }

  // 6. State.
  check_transfer(1);
  check_transfer(2);
  std::cout << "OK" << std::endl;
}
