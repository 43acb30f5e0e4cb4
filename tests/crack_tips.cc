// SPDX-License-Identifier: GPL-3.0-or-later
//
// Unit test of crack tips (fracture/crack_tips.h) and of carrying dof
// values to moved vertices (state_transfer::interpolate_moved()), on a
// 6 x 6 grid of unit squares cut by their diagonals, cracked along y = 3
// from x = 1 to x = 3:
//  1. the maximum tangential stress angle: 0 in mode I, -53.13 degrees
//     for K_I = K_II, -70.53 for K_II alone or a closed crack (K_I < 0),
//     and a root of K_I sin t + K_II (3 cos t - 1) = 0;
//  2. find_crack_tips() finds the two tips with x' pointing out of the
//     crack; stress_intensity_ratio() reads a jump of the faces put in by
//     hand as (K_I, K_II);
//  3. plan_crack_advance() turns a failing edge near the right tip into an
//     advance along the MTS angle: a vertex ahead is moved so that the edge
//     lies on that angle to 1e-12; the triangles stay counter-clockwise, the
//     area stays to 1e-14, and after the crack the new tip lies there with
//     x' along the path; a failing edge far from both tips is kept; only
//     an edge that may crack is taken;
//  4. interpolate_moved() gives, for P1 and P2 (two components), the
//     element's own fields (linear, quadratic) at the moved support points
//     exactly, and leaves the other dofs alone.

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools_interpolate.h>

#include <ndda/fracture/crack_tips.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/mesh/state_transfer.h>

#include <cmath>
#include <iostream>

#include "grids.h"
#include "tests.h"

using namespace ndda;
using dealii::Point;
using dealii::Tensor;
using ndda_tests::check;
using ndda_tests::Field;
using ndda_tests::unit_grid;
using ndda_tests::vertex_at;

namespace
{
  constexpr double degree = M_PI / 180;

  double
  total_area(const geometry::BlockMesh &mesh)
  {
    double sum = 0;
    for (const auto &t : mesh.triangles)
      {
        const auto &x = mesh.vertices;
        sum += 0.5 * ((x[t[1]][0] - x[t[0]][0]) * (x[t[2]][1] - x[t[0]][1]) -
                      (x[t[1]][1] - x[t[0]][1]) * (x[t[2]][0] - x[t[0]][0]));
      }
    return sum;
  }

  void
  check_interpolation(const unsigned int degree)
  {
    CrackableMesh mesh;
    mesh.build(unit_grid(4));
    const dealii::FESystem<2>  fe(dealii::FE_SimplexP<2>(degree), 2);
    dealii::DoFHandler<2>      dofs(mesh.get_triangulation());
    const dealii::MappingFE<2> mapping(dealii::FE_SimplexP<2>(1));
    dofs.distribute_dofs(fe);
    std::vector<dealii::types::global_dof_index> cell_dofs;
    std::vector<dealii::types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        cell_dofs.insert(cell_dofs.end(), local.begin(), local.end());
      }
    dealii::Vector<double> u(dofs.n_dofs()), kept;
    dealii::VectorTools::interpolate(mapping, dofs, Field(degree), u);
    kept = u;
    std::vector<Point<2>> before(dofs.n_dofs()), after(dofs.n_dofs());
    dealii::DoFTools::map_dofs_to_support_points(mapping, dofs, before);

    const unsigned int    v            = vertex_at(mesh, Point<2>(2, 2));
    const auto            old_vertices = mesh.get_block_mesh().vertices;
    std::vector<Point<2>> new_vertices = old_vertices;
    new_vertices[v]                    = Point<2>(2.3, 1.8);
    dealii::Vector<double> copy(u);
    state_transfer::interpolate_moved(fe,
                                      cell_dofs,
                                      mesh.get_block_mesh().triangles,
                                      {v},
                                      old_vertices,
                                      new_vertices,
                                      {&u, &copy});
    mesh.relocate_vertices({v}, {new_vertices[v]}, {new_vertices[v]});
    dealii::DoFTools::map_dofs_to_support_points(mapping, dofs, after);
    unsigned int n_moved = 0;
    double       error   = 0;
    const Field  field(degree);
    // The component of each dof, from the cells.
    std::vector<unsigned int> component(dofs.n_dofs());
    for (std::size_t k = 0; k < cell_dofs.size(); ++k)
      component[cell_dofs[k]] =
        fe.system_to_component_index(k % fe.n_dofs_per_cell()).first;
    for (unsigned int i = 0; i < u.size(); ++i)
      if (before[i].distance(after[i]) > 0)
        {
          ++n_moved;
          error =
            std::max(error,
                     std::abs(u[i] - field.value(after[i], component[i])));
        }
      else
        error = std::max(error, std::abs(u[i] - kept[i]));
    copy -= u;
    error = std::max(error, copy.linfty_norm());
    std::cout << "P" << degree << ": " << n_moved
              << " dofs moved, largest error " << error << std::endl;
    check(n_moved == (degree == 1 ? 2 : 2 + 2 * 6),
          "the dofs at the vertex (and its edges' midpoints) move");
    check(error < 1e-12,
          "the element's own field is carried exactly, the rest kept");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  // 1. The angle.
  const auto residual = [](const double k_I, const double k_II) {
    const double t = fracture::maximum_tangential_stress_angle(k_I, k_II);
    return std::max(k_I, 0.) * std::sin(t) + k_II * (3 * std::cos(t) - 1);
  };
  const double mixed = fracture::maximum_tangential_stress_angle(1, 1);
  std::cout << "MTS angles: mode I "
            << fracture::maximum_tangential_stress_angle(1, 0) / degree
            << ", K_I = K_II " << mixed / degree << ", mode II "
            << fracture::maximum_tangential_stress_angle(0, 1) / degree
            << ", closed "
            << fracture::maximum_tangential_stress_angle(-1, 1) / degree
            << std::endl;
  check(std::abs(fracture::maximum_tangential_stress_angle(1, 0)) < 1e-15,
        "mode I runs straight");
  check(std::abs(mixed / degree + 53.1301) < 1e-4, "K_I = K_II: -53.13");
  check(std::abs(fracture::maximum_tangential_stress_angle(0, 1) / degree +
                 70.5288) < 1e-4,
        "mode II: -70.53");
  check(fracture::maximum_tangential_stress_angle(-1, 1) ==
          fracture::maximum_tangential_stress_angle(0, 1),
        "a closed crack counts as K_I = 0");
  check(std::abs(residual(1, 0.3)) < 1e-12 &&
          std::abs(residual(0.2, -1)) < 1e-12,
        "the angle solves 7.11");

  // 2. Tips.
  CrackableMesh mesh;
  mesh.build(unit_grid(6));
  mesh.crack(
    {{{vertex_at(mesh, Point<2>(1, 3)), vertex_at(mesh, Point<2>(2, 3))}},
     {{vertex_at(mesh, Point<2>(2, 3)), vertex_at(mesh, Point<2>(3, 3))}}});
  auto tips = fracture::find_crack_tips(mesh);
  check(tips.size() == 2, "two tips");
  const auto &x = mesh.get_block_mesh().vertices;
  for (const auto &tip : tips)
    {
      const bool right = x[tip.vertex][0] > 2;
      std::cout << "tip at " << x[tip.vertex] << ", x' " << tip.outward
                << ", behind " << x[tip.behind[0]] << " / " << x[tip.behind[1]]
                << std::endl;
      check(x[tip.vertex].distance(Point<2>(right ? 3 : 1, 3)) < 1e-12 &&
              std::abs(tip.outward[0] - (right ? 1 : -1)) < 1e-12,
            "a tip at each end, x' out of the crack");
    }
  const auto &right = x[tips[0].vertex][0] > 2 ? tips[0] : tips[1];
  // Jump the +y' face's node by (0.01, 0.01): K_I = K_II.
  std::vector<Point<2>> moved = x;
  Tensor<1, 2>          jump;
  jump[0] = jump[1] = 0.01;
  moved[right.behind[0]] += jump;
  const auto k =
    fracture::stress_intensity_ratio(right, moved, mesh.get_initial_vertices());
  check(std::abs(k[0] - 0.01) < 1e-15 && std::abs(k[1] - 0.01) < 1e-15,
        "the faces' jump gives K_I and K_II");

  // 3. An advance.
  mesh.set_vertices(moved);
  const double area = total_area(mesh.get_block_mesh());
  const std::vector<std::array<unsigned int, 2>> failing = {
    {{vertex_at(mesh, Point<2>(3, 3)), vertex_at(mesh, Point<2>(4, 3))}},
    {{vertex_at(mesh, Point<2>(5, 0)), vertex_at(mesh, Point<2>(5, 1))}}};
  const auto crackable =
    fracture::find_interior_edges(mesh.get_block_mesh().triangles,
                                  mesh.get_block_mesh().vertices.size());
  // Only the edge straight ahead may crack: the tip advances along it,
  // its far vertex moved onto the MTS angle.
  const unsigned int ahead = vertex_at(mesh, Point<2>(4, 3));
  const auto         only_ahead =
    fracture::plan_crack_advance(mesh,
                                 failing,
                                 moved,
                                 0.,
                                 {{{{vertex_at(mesh, Point<2>(3, 3)), ahead}},
                                   {{0, 0}}}},
                                 {});
  check(only_ahead.advances.size() == 1 &&
          only_ahead.advances[0].target == ahead,
        "a tip advances only along an edge that may crack");
  const auto plan =
    fracture::plan_crack_advance(mesh, failing, moved, 0., crackable, {});
  check(plan.advances.size() == 1 && plan.moved.size() == 1 &&
          plan.edges.size() == 2,
        "one advance with a vertex moved; the far edge kept");
  const auto &advance = plan.advances[0];
  std::cout << "advance from " << advance.tip_position << " to "
            << advance.target_to << " (was " << advance.target_from
            << "), edge at " << advance.edge_angle / degree << " deg, MTS "
            << advance.mts_angle / degree << std::endl;
  // x' runs to the tip from the middle of the faces' far ends, which the
  // jump moved: the angle is the MTS angle of K_I = K_II nearly.
  check(std::abs(advance.edge_angle - advance.mts_angle) < 1e-12 &&
          std::abs(advance.mts_angle - mixed) < 0.5 * degree,
        "the edge lies on the MTS angle");
  mesh.relocate_vertices(plan.moved, plan.position, plan.initial_position);
  CrackableMesh::check(mesh.get_block_mesh());
  check(std::abs(total_area(mesh.get_block_mesh()) - area) < 1e-14 * area,
        "the move keeps the area");
  mesh.crack(plan.edges);
  tips       = fracture::find_crack_tips(mesh);
  bool found = false;
  for (const auto &tip : tips)
    if (mesh.get_block_mesh().vertices[tip.vertex].distance(advance.target_to) <
        1e-12)
      {
        found = true;
        const Tensor<1, 2> path =
          (advance.target_to - advance.tip_position) /
          advance.target_to.distance(advance.tip_position);
        check((tip.outward - path).norm() < 1e-12,
              "x' of the new tip runs along the path");
      }
  check(found, "the new tip is where the advance went");

  // 4. Carrying values.
  check_interpolation(1);
  check_interpolation(2);
  std::cout << "OK" << std::endl;
}
