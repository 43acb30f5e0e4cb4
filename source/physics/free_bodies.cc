// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rigid-body motions that nothing holds (issue 17): a quasi-static
// scene whose stiffness matrix is singular is named before the run, not
// found after ten step cuts as a displacement increment of 1e11 m.

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/base/utilities.h>
#include <ndda/contact/contact_detection.h>
#include <ndda/mesh/boundary_edges.h>
#include <ndda/physics/free_bodies.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace ndda
{
  namespace
  {
    /** Union-find with path halving. */
    struct Partition
    {
      explicit Partition(const unsigned int n)
        : parent(n)
      {
        std::iota(parent.begin(), parent.end(), 0u);
      }

      unsigned int
      find(unsigned int i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }

      void
      join(const unsigned int a, const unsigned int b)
      {
        const unsigned int ra = find(a), rb = find(b);
        if (ra != rb)
          parent[std::max(ra, rb)] = std::min(ra, rb);
      }

      std::vector<unsigned int> parent;
    };


    /** A body: a connected piece of the mesh. */
    struct Body
    {
      unsigned int block = 0;
      Point<2>     centre;
      /// The diagonal of its bounding box (scales the rotation).
      double size = 0;
    };


    /**
     * The motion of a null vector @p v (translation, rotation scaled by
     * size, per body of @p members) in words.
     */
    std::string
    describe_motion(const dealii::Vector<double>    &v,
                    const std::vector<unsigned int> &members,
                    const std::vector<Body>         &bodies)
    {
      unsigned int largest = 0;
      double       norm    = 0;
      for (unsigned int k = 0; k < members.size(); ++k)
        {
          const double n = std::hypot(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
          if (n > norm)
            {
              norm    = n;
              largest = k;
            }
        }
      const Body  &body = bodies[members[largest]];
      const double a = v[3 * largest], b = v[3 * largest + 1];
      const double theta = v[3 * largest + 2] / body.size;
      // Figures below 1e-9 of the body's size are rounding.
      const auto clean = [&](const double x) {
        return std::abs(x) < 1e-9 * body.size ? 0. : x;
      };
      std::ostringstream out;
      out.precision(4);
      if (std::abs(theta) * body.size < 1e-6 * norm)
        {
          const double length = std::hypot(a, b);
          out << "translate along (" << clean(a / length) << ", "
              << clean(b / length) << ")";
        }
      else
        // u(p) = t + theta k x (p - c) vanishes at the centre of rotation.
        out << "rotate about (" << clean(body.centre[0] - b / theta) << ", "
            << clean(body.centre[1] + a / theta) << ")";
      return out.str();
    }
  } // namespace



  std::vector<FreeMotion>
  free_rigid_motions(const geometry::BlockMesh       &mesh,
                     const DofMap                    &dof_map,
                     const std::vector<RigidSupport> &supports,
                     const unsigned int               max_bodies)
  {
    // The bodies: triangles joined through their vertices (the faces of a
    // crack have vertices of their own).
    const unsigned int n_triangles = mesh.triangles.size();
    Partition          pieces(mesh.vertices.size());
    for (const auto &t : mesh.triangles)
      {
        pieces.join(t[0], t[1]);
        pieces.join(t[0], t[2]);
      }
    std::vector<unsigned int> body_of_root(mesh.vertices.size(),
                                           numbers::invalid_unsigned_int);
    std::vector<Body>         bodies;
    std::vector<unsigned int> body_of_triangle(n_triangles);
    std::vector<Point<2>>     lower, upper;
    std::vector<double>       area;
    for (unsigned int c = 0; c < n_triangles; ++c)
      {
        const auto        &t    = mesh.triangles[c];
        const unsigned int root = pieces.find(t[0]);
        if (body_of_root[root] == numbers::invalid_unsigned_int)
          {
            body_of_root[root] = bodies.size();
            Body body;
            body.block = mesh.cell_block[c];
            bodies.push_back(body);
            lower.push_back(mesh.vertices[t[0]]);
            upper.push_back(mesh.vertices[t[0]]);
            area.push_back(0);
          }
        const unsigned int k = body_of_root[root];
        body_of_triangle[c]  = k;
        const Point<2> &p0 = mesh.vertices[t[0]], &p1 = mesh.vertices[t[1]],
                       &p2 = mesh.vertices[t[2]];
        const double a     = 0.5 * std::abs((p1 - p0)[0] * (p2 - p0)[1] -
                                        (p1 - p0)[1] * (p2 - p0)[0]);
        bodies[k].centre += a * (Point<2>() + (p0 + p1 + p2) / 3.);
        area[k] += a;
        for (const Point<2> *p : {&p0, &p1, &p2})
          for (unsigned int d = 0; d < 2; ++d)
            {
              lower[k][d] = std::min(lower[k][d], (*p)[d]);
              upper[k][d] = std::max(upper[k][d], (*p)[d]);
            }
      }
    const unsigned int n_bodies = bodies.size();
    for (unsigned int k = 0; k < n_bodies; ++k)
      {
        bodies[k].centre /= std::max(area[k], 1e-300);
        bodies[k].size = std::max(upper[k].distance(lower[k]), 1e-300);
      }

    // The body of every dof, through the cells (cell index = triangle).
    std::vector<unsigned int> body_of_dof(dof_map.n_dofs,
                                          numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < dof_map.n_cells() && c < n_triangles; ++c)
      {
        const auto *dofs = dof_map.dofs_of_cell(c);
        for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
          body_of_dof[dofs[i]] = body_of_triangle[c];
      }
    const auto body_of = [&](const RigidSupport::index dof) {
      return dof < body_of_dof.size() ? body_of_dof[dof] :
                                        numbers::invalid_unsigned_int;
    };

    // Groups of bodies linked by supports; n_bodies stands for the ground.
    Partition groups(n_bodies + 1);
    for (const auto &s : supports)
      {
        const unsigned int a = body_of(s.dofs[0]), b = body_of(s.dofs[1]);
        if (a == numbers::invalid_unsigned_int)
          continue;
        groups.join(a, b == numbers::invalid_unsigned_int ? n_bodies : b);
      }
    std::vector<std::vector<unsigned int>> members(n_bodies + 1);
    for (unsigned int k = 0; k < n_bodies; ++k)
      members[groups.find(k)].push_back(k);

    std::vector<FreeMotion> free;
    const unsigned int      ground = groups.find(n_bodies);
    const auto blocks_of           = [&](const std::vector<unsigned int> &m) {
      std::vector<unsigned int> blocks;
      for (const unsigned int k : m)
        blocks.push_back(bodies[k].block);
      std::sort(blocks.begin(), blocks.end());
      blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
      return blocks;
    };
    for (unsigned int root = 0; root < n_bodies; ++root)
      if (!members[root].empty() && root != ground)
        free.push_back({blocks_of(members[root]), ""});

    // Mechanisms of the held group(s): the rank of the support rows. The
    // column of body k: (u_x, u_y, theta * size) of its rigid motion.
    std::vector<unsigned int> held;
    for (unsigned int root = 0; root <= n_bodies; ++root)
      if (groups.find(root) == ground)
        for (const unsigned int k : members[root])
          held.push_back(k);
    if (held.empty() || held.size() > max_bodies)
      return free;
    std::sort(held.begin(), held.end());
    const auto column = [&](const unsigned int body) {
      return 3 *
             static_cast<unsigned int>(
               std::lower_bound(held.begin(), held.end(), body) - held.begin());
    };
    const unsigned int                           n = 3 * held.size();
    dealii::LAPACKFullMatrix<double>             normal(n, n);
    std::vector<std::pair<unsigned int, double>> row;
    for (const auto &s : supports)
      {
        // Only the rows of the held group (the others are free already).
        const unsigned int held_body = body_of(s.dofs[0]);
        if (held_body == numbers::invalid_unsigned_int ||
            groups.find(held_body) != ground)
          continue;
        row.clear();
        for (unsigned int end = 0; end < 2; ++end)
          {
            const unsigned int k = body_of(s.dofs[end]);
            if (k == numbers::invalid_unsigned_int)
              continue;
            const double       sign = end == 0 ? 1. : -1.;
            const Body        &body = bodies[k];
            const auto         r    = s.points[end] - body.centre;
            const unsigned int j    = column(k);
            row.emplace_back(j, sign * s.direction[0]);
            row.emplace_back(j + 1, sign * s.direction[1]);
            row.emplace_back(j + 2,
                             sign *
                               (-s.direction[0] * r[1] +
                                s.direction[1] * r[0]) /
                               body.size);
          }
        if (row.empty())
          continue;
        for (const auto &[i, a] : row)
          for (const auto &[j, b] : row)
            normal(i, j) += a * b;
      }
    double trace = 0;
    for (unsigned int i = 0; i < n; ++i)
      trace += normal(i, i);
    dealii::Vector<double>     eigenvalues;
    dealii::FullMatrix<double> eigenvectors;
    normal.compute_eigenvalues_symmetric(
      -1, 1e-12 * trace, 1e-14 * trace, eigenvalues, eigenvectors);
    for (unsigned int m = 0; m < eigenvalues.size(); ++m)
      {
        dealii::Vector<double> v(n);
        for (unsigned int i = 0; i < n; ++i)
          v[i] = eigenvectors(i, m);
        std::vector<unsigned int> moving;
        const double              largest = v.linfty_norm();
        for (unsigned int k = 0; k < held.size(); ++k)
          if (std::hypot(v[3 * k], v[3 * k + 1], v[3 * k + 2]) > 1e-6 * largest)
            moving.push_back(held[k]);
        free.push_back({blocks_of(moving), describe_motion(v, held, bodies)});
      }
    return free;
  }



  std::vector<RigidSupport>
  rigid_supports(const geometry::BlockMesh &mesh,
                 const DofMap              &dof_map,
                 const Constraints         &constraints,
                 const BoltSprings         &bolts,
                 const double               touch_distance)
  {
    const Tensor<1, 2>        x({1., 0.}), y({0., 1.});
    std::vector<RigidSupport> supports;
    const auto hold = [&](const std::array<RigidSupport::index, 2> &dofs,
                          const std::array<Point<2>, 2>            &points,
                          const Tensor<1, 2>                       &direction) {
      RigidSupport s;
      s.dofs      = dofs;
      s.points    = points;
      s.direction = direction;
      supports.push_back(s);
    };
    const auto none = dealii::numbers::invalid_dof_index;
    for (const auto &nc : constraints.constrained_nodes())
      if (nc.type == parameters::ConstraintType::roller)
        hold({{nc.dofs[0], none}}, {{nc.position, nc.position}}, nc.normal);
      else
        for (const auto &direction : {x, y})
          hold({{nc.dofs[0], none}}, {{nc.position, nc.position}}, direction);

    // Bolts: their anchors are mesh vertices.
    std::vector<unsigned int> vertex_of_dof(dof_map.n_dofs,
                                            numbers::invalid_unsigned_int);
    for (unsigned int v = 0; v < dof_map.vertex_dofs.size(); ++v)
      vertex_of_dof[dof_map.vertex_dofs[v][0]] = v;
    const auto anchors = bolts.anchor_dofs();
    for (unsigned int b = 0; b + 1 < anchors.size(); b += 2)
      {
        const unsigned int v0 = vertex_of_dof[anchors[b]];
        const unsigned int v1 = vertex_of_dof[anchors[b + 1]];
        if (v0 == numbers::invalid_unsigned_int ||
            v1 == numbers::invalid_unsigned_int)
          continue;
        const Point<2> &p0 = mesh.vertices[v0], &p1 = mesh.vertices[v1];
        if (p0.distance(p1) > 0)
          hold({{anchors[b], anchors[b + 1]}},
               {{p0, p1}},
               (p1 - p0) / p0.distance(p1));
      }

    // Contacts that touch: a vertex and the edge it lies on.
    if (touch_distance >= 0)
      {
        const auto edges = boundary_edges(mesh);
        for (const auto &c :
             contact::detect(mesh.vertices, edges, touch_distance))
          {
            const auto &edge = edges[c.edge];
            const auto  dofs = std::array<RigidSupport::index, 2>{
               {dof_map.vertex_dofs[c.vertex][0],
                dof_map.vertex_dofs[edge.v0][0]}};
            const Point<2> &p = mesh.vertices[c.vertex];
            for (const auto &direction : {x, y})
              hold(dofs, {{p, p}}, direction);
          }
      }
    return supports;
  }



  void
  require_held_bodies(const geometry::BlockMesh       &mesh,
                      const DofMap                    &dof_map,
                      const std::vector<RigidSupport> &supports,
                      const std::string               &analysis)
  {
    const auto free = free_rigid_motions(mesh, dof_map, supports);
    if (free.empty())
      return;
    std::ostringstream message;
    message << analysis
            << " solves K d = f without inertia, so every block must be "
               "held, but ";
    for (unsigned int i = 0; i < free.size() && i < 5; ++i)
      {
        const auto &f = free[i];
        message << (i > 0 ? "; " : "")
                << (f.blocks.size() == 1 ? "block " : "blocks ");
        for (unsigned int j = 0; j < f.blocks.size() && j < 5; ++j)
          message << (j > 0 ? ", '" : "'") << mesh.block_names[f.blocks[j]]
                  << "'";
        if (f.blocks.size() > 5)
          message << " and " << f.blocks.size() - 5 << " more";
        if (f.motion.empty())
          message << (f.blocks.size() == 1 ? " has" : " have")
                  << " no boundary condition and touch"
                  << (f.blocks.size() == 1 ? "es" : "") << " no held block";
        else
          message << " can still move as a rigid body: "
                  << (f.blocks.size() == 1 ? "it " : "they ")
                  << (f.blocks.size() == 1 ?
                        f.motion.substr(0, f.motion.find(' ')) + "s" +
                          f.motion.substr(f.motion.find(' ')) :
                        f.motion);
      }
    if (free.size() > 5)
      message << "; and " << free.size() - 5 << " more free motions";
    message << ". Hold every block with a boundary condition, by a bolt, or "
               "by touching (not just nearly touching) a held block, or use "
               "Control/Analysis type = static or dynamic.";
    AssertThrow(false, dealii::ExcMessage(message.str()));
  }
} // namespace ndda
