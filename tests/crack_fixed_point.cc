// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fixed point at a vertex that a crack splits (fracture issue): every
// copy of the vertex stays fixed. A 1 m square hangs from a fixed point at
// its centre under gravity; two interior edges through the centre are
// cracked between steps (Simulator::crack_edges), which splits the centre
// vertex into two copies. The constraints are found again by position on
// the initial geometry, so both copies must be fixed: after more steps
// every degree of freedom at the centre has zero displacement, and the
// two halves still hang from it.

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 1e-3
  set End time        = 0.02
end
subsection Materials
  set Names = rock
  subsection rock
    set Density          = 2600
    set Young's modulus  = 10e9
    set Poisson's ratio  = 0.25
    set Tensile strength = 1e12
    set Cohesion         = 1e12
    set Fracture         = true
  end
end
subsection Geometry
  set Blocks = block
  subsection block
    set Outer boundary = 0, 0; 1, 0; 1, 1; 0, 1
    set Material  = rock
    set Mesh size = 0.25
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = pin
  subsection pin
    set Type   = fixed
    set Points = 0.5, 0.5
  end
end
subsection Output
  set Write vtu = false
end
)";

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);

  ndda::Simulator<2> simulator(read_parameters(scene, "crack_fixed_point"));
  simulator.setup();
  simulator.do_time_step();

  // Two interior edges at the centre vertex, as nearly opposite as the
  // mesh allows: a crack through the centre.
  const auto    &mesh = simulator.get_mesh().get_block_mesh();
  const Point<2> centre(0.5, 0.5);
  unsigned int   c = 0;
  for (unsigned int v = 1; v < mesh.vertices.size(); ++v)
    if (mesh.vertices[v].distance(centre) < mesh.vertices[c].distance(centre))
      c = v;
  check(mesh.vertices[c].distance(centre) < 1e-6, "a vertex at the centre");
  std::vector<unsigned int> neighbours;
  for (const auto &t : mesh.triangles)
    for (unsigned int j = 0; j < 3; ++j)
      if (t[j] == c)
        for (const unsigned int o : {t[(j + 1) % 3], t[(j + 2) % 3]})
          if (std::find(neighbours.begin(), neighbours.end(), o) ==
              neighbours.end())
            neighbours.push_back(o);
  std::array<unsigned int, 2> best{};
  double                      most_opposite = 2;
  for (const unsigned int a : neighbours)
    for (const unsigned int b : neighbours)
      {
        const Tensor<1, 2> da     = mesh.vertices[a] - mesh.vertices[c];
        const Tensor<1, 2> db     = mesh.vertices[b] - mesh.vertices[c];
        const double       cosine = da * db / (da.norm() * db.norm());
        if (a != b && cosine < most_opposite)
          {
            most_opposite = cosine;
            best          = {{a, b}};
          }
      }
  const unsigned int                       n_vertices = mesh.vertices.size();
  std::vector<std::array<unsigned int, 2>> edges;
  for (const unsigned int b : best)
    edges.push_back({{std::min(c, b), std::max(c, b)}});
  simulator.crack_edges(edges);
  const unsigned int n_copies =
    std::count_if(simulator.get_mesh().get_block_mesh().vertices.begin(),
                  simulator.get_mesh().get_block_mesh().vertices.end(),
                  [&](const Point<2> &p) { return p.distance(centre) < 1e-3; });
  std::cout << "cracked two edges through the centre (angle between them "
            << std::acos(most_opposite) * 180 / M_PI << " deg): "
            << simulator.get_mesh().get_block_mesh().vertices.size() -
                 n_vertices
            << " new vertices, " << n_copies << " copies of the centre"
            << std::endl;
  check(n_copies == 2, "the centre vertex is split in two");

  while (simulator.get_time() < 0.02 - 1e-12)
    simulator.do_time_step();

  // Every dof whose support point is (initially) the centre.
  const auto           &dofs = simulator.get_dof_handler();
  std::vector<Point<2>> x(dofs.n_dofs());
  DoFTools::map_dofs_to_support_points(simulator.get_mapping(), dofs, x);
  const auto  &u       = simulator.get_displacement();
  double       largest = 0, elsewhere = 0;
  unsigned int n_at_centre = 0;
  for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
    {
      // The support points are on the present geometry: a copy of the
      // centre that is not fixed has fallen by millimetres by now.
      const double component_u = u[i];
      if (x[i].distance(centre) < 1e-4)
        {
          ++n_at_centre;
          largest = std::max(largest, std::abs(component_u));
        }
      else
        elsewhere = std::max(elsewhere, std::abs(component_u));
    }
  std::cout << "after 0.02 s: " << n_at_centre
            << " dofs at the centre, largest displacement there " << largest
            << " m; elsewhere up to " << elsewhere << " m" << std::endl;
  check(n_at_centre == 4, "both copies of the centre have their dofs there");
  check(largest < 1e-12, "every copy of the fixed point stays fixed");
  check(elsewhere > 1e-7, "the rest of the block moves");
  std::cout << "OK" << std::endl;
}
