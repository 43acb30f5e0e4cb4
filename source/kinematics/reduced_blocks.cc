// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>

#include <ndda/kinematics/reduced_blocks.h>

#include <algorithm>
#include <cmath>

namespace ndda
{
  namespace kinematics
  {
    using namespace dealii;

    namespace
    {
      /**
       * The pseudo-inverse of the symmetric positive semi-definite @p g
       * (k x k, a normal matrix A^T A) and an orthonormal basis of its null
       * space (as columns), by cyclic Jacobi rotations; eigenvalues below
       * 1e-12 of the largest count as zero.
       */
      std::pair<FullMatrix<double>, FullMatrix<double>>
      pseudo_inverse(FullMatrix<double> g)
      {
        const unsigned int k = g.m();
        FullMatrix<double> v(k, k);
        for (unsigned int i = 0; i < k; ++i)
          v(i, i) = 1;
        for (unsigned int sweep = 0; sweep < 60; ++sweep)
          {
            double off = 0, diagonal = 0;
            for (unsigned int i = 0; i < k; ++i)
              {
                diagonal += g(i, i) * g(i, i);
                for (unsigned int j = i + 1; j < k; ++j)
                  off += g(i, j) * g(i, j);
              }
            if (off <= 1e-30 * diagonal || off == 0.)
              break;
            for (unsigned int p = 0; p < k; ++p)
              for (unsigned int q = p + 1; q < k; ++q)
                {
                  if (g(p, q) == 0.)
                    continue;
                  // The rotation that zeroes g(p, q).
                  const double tau = (g(q, q) - g(p, p)) / (2 * g(p, q));
                  const double t   = (tau >= 0 ? 1. : -1.) /
                                   (std::abs(tau) + std::sqrt(1 + tau * tau));
                  const double c = 1 / std::sqrt(1 + t * t), s = t * c;
                  for (unsigned int i = 0; i < k; ++i)
                    {
                      const double gp = g(i, p), gq = g(i, q);
                      g(i, p) = c * gp - s * gq;
                      g(i, q) = s * gp + c * gq;
                    }
                  for (unsigned int i = 0; i < k; ++i)
                    {
                      const double gp = g(p, i), gq = g(q, i);
                      g(p, i) = c * gp - s * gq;
                      g(q, i) = s * gp + c * gq;
                    }
                  for (unsigned int i = 0; i < k; ++i)
                    {
                      const double vp = v(i, p), vq = v(i, q);
                      v(i, p) = c * vp - s * vq;
                      v(i, q) = s * vp + c * vq;
                    }
                }
          }
        double largest = 0;
        for (unsigned int i = 0; i < k; ++i)
          largest = std::max(largest, g(i, i));
        FullMatrix<double>        inverse(k, k);
        std::vector<unsigned int> null;
        for (unsigned int e = 0; e < k; ++e)
          if (g(e, e) <= 1e-12 * largest || largest == 0.)
            null.push_back(e);
          else
            for (unsigned int i = 0; i < k; ++i)
              for (unsigned int j = 0; j < k; ++j)
                inverse(i, j) += v(i, e) * v(j, e) / g(e, e);
        FullMatrix<double> null_space(k, null.size());
        for (unsigned int c = 0; c < null.size(); ++c)
          for (unsigned int i = 0; i < k; ++i)
            null_space(i, c) = v(i, null[c]);
        return {inverse, null_space};
      }



      /**
       * @p count rows of @p a that are well independent, by pivoting: the
       * longest row, then the longest after removing the chosen ones'
       * directions, and so on. Throws if @p a has fewer independent rows.
       */
      std::vector<unsigned int>
      pivot_rows(const FullMatrix<double> &a, const unsigned int count)
      {
        FullMatrix<double>        w(a);
        std::vector<unsigned int> chosen;
        std::vector<bool>         taken(a.m(), false);
        double                    first = 0;
        for (unsigned int s = 0; s < count; ++s)
          {
            unsigned int best = numbers::invalid_unsigned_int;
            double       norm = 0;
            for (unsigned int i = 0; i < w.m(); ++i)
              {
                double n = 0;
                for (unsigned int j = 0; j < w.n(); ++j)
                  n += w(i, j) * w(i, j);
                if (!taken[i] && n > norm)
                  {
                    norm = n;
                    best = i;
                  }
              }
            if (s == 0)
              first = norm;
            AssertThrow(best != numbers::invalid_unsigned_int &&
                          norm > 1e-20 * first,
                        ExcMessage("A reduced block's nodes do not determine "
                                   "its unknowns (its nodes are collinear?)."));
            chosen.push_back(best);
            taken[best] = true;
            Vector<double> q(w.n());
            for (unsigned int j = 0; j < w.n(); ++j)
              q[j] = w(best, j) / std::sqrt(norm);
            for (unsigned int i = 0; i < w.m(); ++i)
              {
                double dot = 0;
                for (unsigned int j = 0; j < w.n(); ++j)
                  dot += w(i, j) * q[j];
                for (unsigned int j = 0; j < w.n(); ++j)
                  w(i, j) -= dot * q[j];
              }
          }
        return chosen;
      }



      /** The present position of every node of @p dof_map on @p mesh. */
      std::vector<Point<2>>
      node_positions(const CrackableMesh &mesh, const DofMap &dof_map)
      {
        const auto           &support = dof_map.fe->get_unit_support_points();
        std::vector<Point<2>> position(dof_map.node_dofs.size());
        for (const auto &cell :
             mesh.get_triangulation().active_cell_iterators())
          {
            const auto *dofs = dof_map.dofs_of_cell(cell->active_cell_index());
            const Tensor<1, 2> e1 = cell->vertex(1) - cell->vertex(0);
            const Tensor<1, 2> e2 = cell->vertex(2) - cell->vertex(0);
            for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
              if (dof_map.local_component[i] == 0)
                position[dof_map.dof_to_node[dofs[i]]] =
                  cell->vertex(0) + support[i][0] * e1 + support[i][1] * e2;
          }
        return position;
      }



      /** Whether the rigid motions of @p block's nodes lie in the span of
       * its basis @p b (2n x k). */
      bool
      holds_rigid_motions(const FullMatrix<double>        &b,
                          const std::vector<Tensor<1, 2>> &r)
      {
        FullMatrix<double> normal(b.n(), b.n());
        b.Tmmult(normal, b);
        const FullMatrix<double> inverse = pseudo_inverse(normal).first;
        for (unsigned int mode = 0; mode < 3; ++mode)
          {
            Vector<double> u(b.m()), q(b.n()), bt_u(b.n()), fit(b.m());
            for (unsigned int i = 0; i < r.size(); ++i)
              {
                u[2 * i]     = mode == 0 ? 1. : mode == 1 ? 0. : -r[i][1];
                u[2 * i + 1] = mode == 0 ? 0. : mode == 1 ? 1. : r[i][0];
              }
            b.Tvmult(bt_u, u);
            inverse.vmult(q, bt_u);
            b.vmult(fit, q);
            fit -= u;
            if (fit.l2_norm() > 1e-8 * u.l2_norm())
              return false;
          }
        return true;
      }
    } // namespace



    void
    ReducedBlocks::setup(
      const CrackableMesh                        &mesh,
      const DofMap                               &dof_map,
      const BlockFrames                          &frames,
      const std::vector<const BlockKinematics *> &block_model,
      const Constraints                          &constraints)
    {
      this->dof_map = &dof_map;
      this->frames  = &frames;
      blocks.clear();
      const unsigned int n_nodes = dof_map.node_dofs.size();
      node_block.assign(n_nodes, invalid);
      node_local.assign(n_nodes, invalid);
      std::vector<unsigned int> reduced(mesh.n_blocks(), invalid);
      for (unsigned int b = 0; b < mesh.n_blocks(); ++b)
        if (block_model[b] != nullptr && block_model[b]->n_unknowns() > 0)
          {
            reduced[b] = blocks.size();
            blocks.push_back(Block());
            blocks.back().mesh_block   = b;
            blocks.back().model        = block_model[b];
            blocks.back().global_frame = frames.keeps_global_frame(b);
          }
      if (blocks.empty())
        return;
      for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
        {
          const unsigned int r = reduced[mesh.block_of_cell(c)];
          if (r == invalid)
            continue;
          const auto *dofs = dof_map.dofs_of_cell(c);
          for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
            {
              const unsigned int n = dof_map.dof_to_node[dofs[i]];
              if (node_block[n] != invalid)
                continue;
              node_block[n] = r;
              node_local[n] = blocks[r].nodes.size();
              blocks[r].nodes.push_back(n);
            }
        }

      // B of every block, on its nodes' positions relative to its
      // centroid, in its frame, over its size.
      const std::vector<Point<2>> position = node_positions(mesh, dof_map);
      for (auto &block : blocks)
        build_basis(block, position, mesh.get_block_names()[block.mesh_block]);
      if (constraints.exact())
        add_constraint_rows(constraints);
      for (auto &block : blocks)
        build_lines(block);
    }



    void
    ReducedBlocks::build_basis(Block                       &block,
                               const std::vector<Point<2>> &position,
                               const std::string           &name) const
    {
      Tensor<1, 2> centroid;
      for (const auto n : block.nodes)
        centroid += position[n];
      centroid /= block.nodes.size();
      double size = 0;
      for (const auto n : block.nodes)
        size = std::max(size, (position[n] - centroid).norm());
      const auto [c, s]           = frames->node_rotation(block.nodes[0]);
      const unsigned int        k = block.model->n_unknowns();
      std::vector<Tensor<1, 2>> r(block.nodes.size());
      block.basis.reinit(2 * block.nodes.size(), k);
      for (unsigned int i = 0; i < block.nodes.size(); ++i)
        {
          const Tensor<1, 2> x = (position[block.nodes[i]] - centroid) / size;
          r[i][0]              = c * x[0] + s * x[1];
          r[i][1]              = -s * x[0] + c * x[1];
          block.model->basis(r[i],
                             &block.basis(2 * i, 0),
                             &block.basis(2 * i + 1, 0));
        }
      AssertThrow(holds_rigid_motions(block.basis, r),
                  ExcMessage("Kinematics of block '" + name +
                             "': the model's space does not hold the "
                             "rigid motions (translations and rotation) "
                             "of the block."));
    }



    void
    ReducedBlocks::add_constraint_rows(const Constraints &constraints)
    {
      const auto &nodes = constraints.constrained_nodes();
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          const unsigned int n = dof_map->dof_to_node[nodes[i].dofs[0]];
          if (node_block[n] == invalid)
            continue;
          Block &block      = blocks[node_block[n]];
          const auto [c, s] = frames->node_rotation(n);
          if (nodes[i].type == parameters::ConstraintType::roller)
            {
              const Tensor<1, 2> &g = nodes[i].normal;
              block.rows.push_back(
                Tensor<1, 2>({c * g[0] + s * g[1], -s * g[0] + c * g[1]}));
              block.row_constraint.push_back(i);
              block.row_node.push_back(node_local[n]);
            }
          else
            for (unsigned int d = 0; d < 2; ++d)
              {
                Tensor<1, 2> e;
                e[d] = 1;
                block.rows.push_back(e);
                block.row_constraint.push_back(i);
                block.row_node.push_back(node_local[n]);
              }
        }
    }



    void
    ReducedBlocks::build_lines(Block &block) const
    {
      const unsigned int k = block.model->n_unknowns();
      // C B (rows x k), and q = P g + N z from its normal matrix.
      FullMatrix<double> cb(block.rows.size(), k);
      for (unsigned int r = 0; r < block.rows.size(); ++r)
        {
          const unsigned int node = block.row_node[r];
          for (unsigned int j = 0; j < k; ++j)
            cb(r, j) = block.rows[r][0] * block.basis(2 * node, j) +
                       block.rows[r][1] * block.basis(2 * node + 1, j);
        }
      // A block without constraint rows has C B empty: its normal matrix is
      // zero (all of its unknowns free) and it has no particular part. The
      // products are skipped, not made of empty matrices, which FullMatrix
      // refuses in Debug builds.
      FullMatrix<double> normal(k, k);
      if (!block.rows.empty())
        cb.Tmmult(normal, cb);
      auto [inverse, null_space] = pseudo_inverse(normal);
      block.particular.reinit(k, block.rows.size());
      if (!block.rows.empty())
        inverse.mTmult(block.particular, cb);

      // B N, its masters and the lines: coefficients = B N (B N)_M^-1.
      const unsigned int m = null_space.n();
      if (m == 0)
        {
          // The constraints fix every unknown of the block: no masters, and
          // every dof is a line without entries. (The products below would
          // be of empty matrices, which FullMatrix refuses in Debug builds.)
          block.masters.clear();
          block.coefficients.reinit(0, 0);
          return;
        }
      FullMatrix<double> bn(block.basis.m(), m);
      block.basis.mmult(bn, null_space);
      block.masters = pivot_rows(bn, m);
      FullMatrix<double> at_masters(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          at_masters(i, j) = bn(block.masters[i], j);
      if (m > 0)
        at_masters.gauss_jordan();
      block.coefficients.reinit(bn.m(), m);
      bn.mmult(block.coefficients, at_masters);
    }



    void
    ReducedBlocks::add_lines(AffineConstraints<double> &lines) const
    {
      for (const auto &block : blocks)
        {
          std::vector<index> dofs(2 * block.nodes.size());
          for (unsigned int i = 0; i < block.nodes.size(); ++i)
            for (unsigned int d = 0; d < 2; ++d)
              dofs[2 * i + d] = dof_map->node_dofs[block.nodes[i]][d];
          std::vector<bool> master(dofs.size(), false);
          for (const auto j : block.masters)
            master[j] = true;
          for (unsigned int j = 0; j < dofs.size(); ++j)
            {
              if (master[j])
                continue;
              lines.add_line(dofs[j]);
              for (unsigned int s = 0; s < block.masters.size(); ++s)
                if (block.coefficients(j, s) != 0.)
                  lines.add_entry(dofs[j],
                                  dofs[block.masters[s]],
                                  block.coefficients(j, s));
            }
        }
    }



    void
    ReducedBlocks::prescribed_increment(const std::vector<Tensor<1, 2>> &target,
                                        Vector<double> &increment) const
    {
      for (const auto &block : blocks)
        {
          if (block.rows.empty())
            continue;
          // g in the block's frame, q = P g, B q back to global components.
          const auto [c, s] = frames->node_rotation(block.nodes[0]);
          Vector<double> g(block.rows.size()), q(block.particular.m()),
            d(block.basis.m());
          for (unsigned int r = 0; r < block.rows.size(); ++r)
            {
              const Tensor<1, 2> &t = target[block.row_constraint[r]];
              g[r]                  = block.rows[r][0] * (c * t[0] + s * t[1]) +
                     block.rows[r][1] * (-s * t[0] + c * t[1]);
            }
          block.particular.vmult(q, g);
          block.basis.vmult(d, q);
          for (unsigned int i = 0; i < block.nodes.size(); ++i)
            {
              const auto &dofs   = dof_map->node_dofs[block.nodes[i]];
              increment[dofs[0]] = c * d[2 * i] - s * d[2 * i + 1];
              increment[dofs[1]] = s * d[2 * i] + c * d[2 * i + 1];
            }
        }
    }



    void
    ReducedBlocks::project(const SparseMatrix<double> &mass,
                           Vector<double>             &velocity,
                           Vector<double>             *inertia_force,
                           const std::vector<bool>    &mesh_blocks) const
    {
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          const Block &block = blocks[b];
          if (!mesh_blocks.empty() && !mesh_blocks[block.mesh_block])
            continue;
          const unsigned int n = block.nodes.size(), k = block.basis.n();
          // The velocity in the block's frame, M v and M B on its dofs
          // (the mass couples a block's dofs only with its own).
          const auto [c, s] = frames->node_rotation(block.nodes[0]);
          Vector<double> v(2 * n), mv(2 * n), f(2 * n);
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto &dofs = dof_map->node_dofs[block.nodes[i]];
              v[2 * i]         = c * velocity[dofs[0]] + s * velocity[dofs[1]];
              v[2 * i + 1]     = -s * velocity[dofs[0]] + c * velocity[dofs[1]];
              if (inertia_force != nullptr)
                {
                  const Vector<double> &a = *inertia_force;
                  f[2 * i]                = c * a[dofs[0]] + s * a[dofs[1]];
                  f[2 * i + 1]            = -s * a[dofs[0]] + c * a[dofs[1]];
                }
            }
          FullMatrix<double> mb(2 * n, k);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int d = 0; d < 2; ++d)
              {
                const index row = dof_map->node_dofs[block.nodes[i]][d];
                for (auto e = mass.begin(row); e != mass.end(row); ++e)
                  {
                    const unsigned int node = dof_map->dof_to_node[e->column()];
                    if (node_block[node] != b)
                      continue;
                    const unsigned int j =
                      2 * node_local[node] +
                      (e->column() == dof_map->node_dofs[node][0] ? 0 : 1);
                    mv[2 * i + d] += e->value() * v[j];
                    for (unsigned int l = 0; l < k; ++l)
                      mb(2 * i + d, l) += e->value() * block.basis(j, l);
                  }
              }
          FullMatrix<double> btmb(k, k);
          block.basis.Tmmult(btmb, mb);
          Vector<double> rhs(k), q(k), fit(2 * n);
          block.basis.Tvmult(rhs, mv);
          const FullMatrix<double> inverse = pseudo_inverse(btmb).first;
          inverse.vmult(q, rhs);
          block.basis.vmult(fit, q);
          const auto put = [&](const Vector<double> &local,
                               Vector<double>       &global) {
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto &dofs = dof_map->node_dofs[block.nodes[i]];
                global[dofs[0]]  = c * local[2 * i] - s * local[2 * i + 1];
                global[dofs[1]]  = s * local[2 * i] + c * local[2 * i + 1];
              }
          };
          put(fit, velocity);
          if (inertia_force == nullptr)
            continue;
          // M a with a the fit of the acceleration: M B (B^T M B)^-1 B^T f.
          block.basis.Tvmult(rhs, f);
          inverse.vmult(q, rhs);
          mb.vmult(fit, q);
          put(fit, *inertia_force);
        }
    }



    bool
    ReducedBlocks::stale(const std::vector<double> &block_rotation) const
    {
      for (const auto &block : blocks)
        if (block.global_frame && !block.model->affine_invariant() &&
            block_rotation[block.mesh_block] != 0.)
          return true;
      return false;
    }



    unsigned int
    ReducedBlocks::n_blocks_of(const BlockKinematics *model) const
    {
      return std::count_if(blocks.begin(),
                           blocks.end(),
                           [model](const Block &b) {
                             return b.model == model;
                           });
    }
  } // namespace kinematics
} // namespace ndda
