// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ndda/parallel/shared_mesh.h>
#include <ndda/postprocess/stress_recovery.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <cmath>

namespace ndda
{
  namespace postprocess
  {
    namespace
    {
      /**
       * The least-squares fit of values at the points of @p from by the
       * complete polynomials of the highest degree m with (m + 1)(m + 2)/2
       * <= its number of points, evaluated at the points of @p to: row r
       * gives the fitted value at point r of @p to from the values at the
       * points of @p from.
       */
      FullMatrix<double>
      fit_to_points(const Quadrature<2> &from, const Quadrature<2> &to)
      {
        unsigned int degree = 0;
        while ((degree + 2) * (degree + 3) / 2 <= from.size())
          ++degree;
        const auto monomials = [degree](const Point<2> &p) {
          std::vector<double> m;
          for (unsigned int total = 0; total <= degree; ++total)
            for (unsigned int i = 0; i <= total; ++i)
              m.push_back(std::pow(p[0], total - i) * std::pow(p[1], i));
          return m;
        };
        const unsigned int n_basis = (degree + 1) * (degree + 2) / 2;
        FullMatrix<double> at_from(from.size(), n_basis);
        for (unsigned int q = 0; q < from.size(); ++q)
          {
            const auto m = monomials(from.point(q));
            for (unsigned int b = 0; b < n_basis; ++b)
              at_from(q, b) = m[b];
          }
        // (A^T A)^-1 A^T: the coefficients from the values.
        FullMatrix<double> normal(n_basis, n_basis);
        at_from.Tmmult(normal, at_from);
        normal.gauss_jordan();
        FullMatrix<double> coefficients(n_basis, from.size());
        normal.mTmult(coefficients, at_from);
        FullMatrix<double> at_to(to.size(), n_basis);
        for (unsigned int r = 0; r < to.size(); ++r)
          {
            const auto m = monomials(to.point(r));
            for (unsigned int b = 0; b < n_basis; ++b)
              at_to(r, b) = m[b];
          }
        FullMatrix<double> result(to.size(), from.size());
        at_to.mmult(result, coefficients);
        return result;
      }


      /**
       * A linear stress a + b (x - c)/L + d (y - c)/L fitted to samples
       * around the centre c, L the farthest sample's distance (so that the
       * normal matrix is well scaled).
       */
      class LinearFit
      {
      public:
        /**
         * Fit @p values at @p points. Returns false, and leaves the fit
         * unusable, if the points do not determine a linear function
         * (fewer than three, or nearly on one line).
         */
        bool
        fit(const Point<2>                            &centre,
            const std::vector<Point<2>>               &points,
            const std::vector<StressRecovery::Stress> &values)
        {
          c = centre;
          L = 0;
          for (const auto &p : points)
            L = std::max(L, p.distance(centre));
          if (points.size() < 3 || L == 0.)
            return false;
          FullMatrix<double>            normal(3, 3);
          std::array<Vector<double>, 3> rhs;
          for (auto &r : rhs)
            r.reinit(3);
          for (unsigned int s = 0; s < points.size(); ++s)
            {
              const auto b = basis(points[s]);
              for (unsigned int i = 0; i < 3; ++i)
                {
                  for (unsigned int j = 0; j < 3; ++j)
                    normal(i, j) += b[i] * b[j];
                  rhs[0](i) += b[i] * values[s][0][0];
                  rhs[1](i) += b[i] * values[s][1][1];
                  rhs[2](i) += b[i] * values[s][0][1];
                }
            }
          // Samples nearly on a line leave the normal matrix nearly
          // singular: refuse a condition number above 1e6 (l1 norms).
          const double       norm = normal.l1_norm();
          FullMatrix<double> inverse(normal);
          inverse.gauss_jordan();
          if (!std::isfinite(inverse.l1_norm()) ||
              norm * inverse.l1_norm() > 1e6)
            return false;
          for (unsigned int k = 0; k < 3; ++k)
            {
              coefficients[k].reinit(3);
              inverse.vmult(coefficients[k], rhs[k]);
            }
          return true;
        }

        /** The fitted stress at @p x. */
        StressRecovery::Stress
        operator()(const Point<2> &x) const
        {
          const auto             b = basis(x);
          StressRecovery::Stress s;
          double                 v[3] = {0, 0, 0};
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int i = 0; i < 3; ++i)
              v[k] += coefficients[k](i) * b[i];
          s[0][0] = v[0];
          s[1][1] = v[1];
          s[0][1] = v[2];
          return s;
        }

      private:
        std::array<double, 3>
        basis(const Point<2> &x) const
        {
          return {{1., (x[0] - c[0]) / L, (x[1] - c[1]) / L}};
        }

        Point<2>                      c;
        double                        L = 0;
        std::array<Vector<double>, 3> coefficients;
      };
    } // namespace



    void
    StressRecovery::recover_by_patches(
      const Mapping<2>                       &mapping,
      const Quadrature<2>                    &quadrature,
      const std::vector<std::vector<Stress>> &stresses)
    {
      const auto        &fe = dof_handler.get_fe();
      const unsigned int n  = dof_handler.n_dofs();

      // Per cell: its dofs, their positions and the stresses' points, on
      // the present geometry; per dof: the cells around it and whether it
      // lies on the boundary of its piece.
      FEValues<2>        at_stress_points(mapping,
                                   fe,
                                   quadrature,
                                   update_quadrature_points);
      FEValues<2>        at_nodes(mapping,
                           fe,
                           Quadrature<2>(fe.get_unit_support_points()),
                           update_quadrature_points);
      const unsigned int n_cells =
        dof_handler.get_triangulation().n_active_cells();
      std::vector<std::vector<types::global_dof_index>> cell_dofs(n_cells);
      std::vector<std::vector<Point<2>>>                cell_nodes(n_cells);
      std::vector<std::vector<Point<2>>>                cell_points(n_cells);
      std::vector<std::vector<unsigned int>>            patch(n);
      std::vector<Point<2>>                             position(n);
      std::vector<bool>                                 on_boundary(n, false);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int c = cell->active_cell_index();
          cell_dofs[c].resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(cell_dofs[c]);
          at_stress_points.reinit(cell);
          at_nodes.reinit(cell);
          cell_points[c] = at_stress_points.get_quadrature_points();
          cell_nodes[c]  = at_nodes.get_quadrature_points();
          for (unsigned int i = 0; i < cell_dofs[c].size(); ++i)
            {
              patch[cell_dofs[c][i]].push_back(c);
              position[cell_dofs[c][i]] = cell_nodes[c][i];
            }
          // A linear element's dof i sits at vertex i.
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              for (unsigned int i = 0; i < cell_dofs[c].size(); ++i)
                for (const unsigned int k : cell->face(f)->vertex_indices())
                  if (cell->face(f)->vertex_index(k) == cell->vertex_index(i))
                    on_boundary[cell_dofs[c][i]] = true;
        }

      std::vector<LinearFit> fits(n);
      std::vector<bool>      fitted(n, false);
      std::vector<Point<2>>  points;
      std::vector<Stress>    values;
      for (types::global_dof_index i = 0; i < n; ++i)
        {
          points.clear();
          values.clear();
          for (const unsigned int c : patch[i])
            for (unsigned int q = 0; q < cell_points[c].size(); ++q)
              {
                points.push_back(cell_points[c][q]);
                values.push_back(stresses[c][q]);
              }
          fitted[i] = fits[i].fit(position[i], points, values);
        }

      // Inner nodes: their own fits. Boundary nodes: the mean of the fits
      // of the inner nodes whose cells touch them.
      std::vector<Stress>       sum(n);
      std::vector<unsigned int> count(n, 0);
      for (types::global_dof_index i = 0; i < n; ++i)
        if (!on_boundary[i] && fitted[i])
          for (const unsigned int c : patch[i])
            for (const auto j : cell_dofs[c])
              if (on_boundary[j])
                {
                  sum[j] += fits[i](position[j]);
                  ++count[j];
                }
      projected_nodes = 0;
      for (types::global_dof_index i = 0; i < n; ++i)
        {
          Stress s;
          if (!on_boundary[i] && fitted[i])
            s = fits[i](position[i]);
          else if (on_boundary[i] && count[i] > 0)
            s = sum[i] / double(count[i]);
          else if (fitted[i])
            s = fits[i](position[i]);
          else
            {
              // A node whose cells alone do not determine a linear fit
              // and that no inner node's cells touch (a corner with one
              // cell): the fit over its cells and their neighbours through
              // a node.
              std::vector<unsigned int> ring;
              for (const unsigned int c : patch[i])
                for (const auto j : cell_dofs[c])
                  ring.insert(ring.end(), patch[j].begin(), patch[j].end());
              std::sort(ring.begin(), ring.end());
              ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
              points.clear();
              values.clear();
              for (const unsigned int c : ring)
                for (unsigned int q = 0; q < cell_points[c].size(); ++q)
                  {
                    points.push_back(cell_points[c][q]);
                    values.push_back(stresses[c][q]);
                  }
              LinearFit wide;
              if (!wide.fit(position[i], points, values))
                {
                  ++projected_nodes;
                  continue;
                }
              s = wide(position[i]);
            }
          components[0](i) = s[0][0];
          components[1](i) = s[1][1];
          components[2](i) = s[0][1];
        }
    }



    void
    StressRecovery::recover(const DoFHandler<2>                    &dofs,
                            const Mapping<2>                       &mapping,
                            const Quadrature<2>                    &quadrature,
                            const Quadrature<2>                    &mass_rule,
                            const std::vector<std::vector<Stress>> &stresses)
    {
      const auto &fe = dofs.get_fe().base_element(0);
      dof_handler.reinit(dofs.get_triangulation());
      dof_handler.distribute_dofs(fe);
      number_dofs_as_on_one_process(dof_handler);
      const unsigned int n = dof_handler.n_dofs();
      AssertThrow(stresses.size() == dofs.get_triangulation().n_active_cells(),
                  ExcMessage("StressRecovery: the stresses are not those of "
                             "the mesh's cells."));

      DynamicSparsityPattern pattern(n, n);
      make_whole_sparsity_pattern(dof_handler, pattern);
      SparsityPattern sparsity;
      sparsity.copy_from(pattern);
      SparseMatrix<double> mass(sparsity);
      for (auto &c : components)
        c.reinit(n);
      std::array<Vector<double>, 3> rhs;
      for (auto &r : rhs)
        r.reinit(n);

      // The stress of a cell is known at the points of the cell
      // quadrature only; between them it is the polynomial of the highest
      // complete degree those points determine (a constant for P1's one
      // point, the linear stress of P2 from its three), fitted by least
      // squares in the unit cell (the mapping is affine), and integrated
      // with the mass quadrature: a stress of that degree is then
      // projected exactly. to_mass_points(r, q) gives the fitted value at
      // mass point r from the value at stress point q.
      const FullMatrix<double> to_mass_points =
        fit_to_points(quadrature, mass_rule);

      FEValues<2>                          values(mapping,
                         fe,
                         mass_rule,
                         update_values | update_JxW_values);
      const unsigned int                   n_local = fe.n_dofs_per_cell();
      const unsigned int                   n_mass  = mass_rule.size();
      FullMatrix<double>                   cell_mass(n_local, n_local);
      std::vector<types::global_dof_index> local(n_local);
      std::vector<Stress>                  sigma_r(n_mass);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const auto &sigma = stresses[cell->active_cell_index()];
          AssertThrow(sigma.size() == quadrature.size(),
                      ExcMessage("StressRecovery: a cell's stresses are not "
                                 "at the points of the cell quadrature."));
          for (unsigned int r = 0; r < n_mass; ++r)
            {
              sigma_r[r] = Stress();
              for (unsigned int q = 0; q < sigma.size(); ++q)
                sigma_r[r] += to_mass_points(r, q) * sigma[q];
            }
          values.reinit(cell);
          cell->get_dof_indices(local);
          cell_mass = 0;
          for (unsigned int r = 0; r < n_mass; ++r)
            for (unsigned int i = 0; i < n_local; ++i)
              {
                const double w = values.shape_value(i, r) * values.JxW(r);
                for (unsigned int j = 0; j < n_local; ++j)
                  cell_mass(i, j) += w * values.shape_value(j, r);
                rhs[0](local[i]) += w * sigma_r[r][0][0];
                rhs[1](local[i]) += w * sigma_r[r][1][1];
                rhs[2](local[i]) += w * sigma_r[r][0][1];
              }
          mass.add(local, cell_mass);
        }

      PreconditionJacobi<SparseMatrix<double>> jacobi;
      jacobi.initialize(mass);
      iterations = 0;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double norm = rhs[k].l2_norm();
          if (norm == 0.)
            continue;
          SolverControl            control(1000, 1e-13 * norm);
          SolverCG<Vector<double>> cg(control);
          cg.solve(mass, components[k], rhs[k], jacobi);
          iterations = std::max(iterations, control.last_step());
        }

      // A linear element: three dofs a cell, one at each vertex.
      projected_nodes = 0;
      if (linear_method == LinearMethod::patch_recovery &&
          fe.n_dofs_per_cell() == 3 && fe.n_dofs_per_vertex() == 1)
        recover_by_patches(mapping, quadrature, stresses);
    }



    void
    StressRecovery::recover(const Simulator<2> &simulator)
    {
      const auto &cache = simulator.get_discretization().element_cache;
      recover(simulator.get_dof_handler(),
              simulator.get_mapping(),
              cache.get_quadrature(),
              cache.get_mass_quadrature(),
              simulator.get_stresses().by_cell());
    }



    StressRecovery::Stress
    StressRecovery::at_dof(const types::global_dof_index i) const
    {
      Stress s;
      s[0][0] = components[0](i);
      s[1][1] = components[1](i);
      s[0][1] = components[2](i);
      return s;
    }



    StressRecovery::Stress
    StressRecovery::at_vertex(const DoFHandler<2>::active_cell_iterator &cell,
                              const unsigned int v) const
    {
      const typename DoFHandler<2>::active_cell_iterator own(
        &dof_handler.get_triangulation(),
        cell->level(),
        cell->index(),
        &dof_handler);
      return at_dof(own->vertex_dof_index(v, 0));
    }
  } // namespace postprocess
} // namespace ndda
