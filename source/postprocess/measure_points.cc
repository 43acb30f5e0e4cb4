// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/base/atomic_file.h>
#include <ndda/postprocess/measure_points.h>

#include <iomanip>
#include <sstream>

namespace ndda
{
  namespace postprocess
  {
    void
    MeasurePoints::setup(const CrackableMesh            &mesh,
                         const dealii::FiniteElement<2> &fe,
                         const DofMap                   &dof_map,
                         const std::vector<Point<2>>    &points,
                         const bool                      keep_histories)
    {
      this->points = points;
      evaluators.clear();
      for (const auto &p : points)
        evaluators.push_back(
          make_point_evaluator(mesh, fe, dof_map, p, "Output/Measure points"));
      if (!keep_histories)
        {
          histories.assign(points.size(), {});
          written_file.clear();
        }
    }



    void
    MeasurePoints::record(const double                  time,
                          const dealii::Vector<double> &displacement,
                          const dealii::Vector<double> &velocity,
                          const StressField            &stresses)
    {
      for (unsigned int m = 0; m < evaluators.size(); ++m)
        {
          const auto   &e = evaluators[m];
          MeasureSample sample;
          sample.time = time;
          for (unsigned int i = 0; i < e.dofs.size(); ++i)
            {
              sample.displacement[e.component[i]] +=
                e.shape_values[i] * displacement[e.dofs[i]];
              sample.velocity[e.component[i]] +=
                e.shape_values[i] * velocity[e.dofs[i]];
            }
          sample.stress = stresses.mean(e.cell);
          histories[m].push_back(sample);
        }
    }



    void
    MeasurePoints::write(const std::string &file_name)
    {
      const bool first = file_name != written_file;
      if (first)
        n_written = 0;
      // One write of all the samples: a run killed at any moment leaves
      // whole lines.
      std::ostringstream history;
      if (first)
        {
          history << "# time";
          for (unsigned int m = 0; m < points.size(); ++m)
            history << "  [point " << m << " at " << points[m][0] << " "
                    << points[m][1]
                    << ": u_x u_y v_x v_y sigma_xx sigma_yy sigma_xy]";
          history << '\n';
        }
      history << std::setprecision(10);
      written_file = file_name;
      if (!histories.empty())
        for (unsigned int s = n_written; s < histories[0].size(); ++s)
          {
            history << histories[0][s].time;
            for (const auto &h : histories)
              history << ' ' << h[s].displacement << ' ' << h[s].velocity << ' '
                      << h[s].stress[0][0] << ' ' << h[s].stress[1][1] << ' '
                      << h[s].stress[0][1];
            history << '\n';
          }
      append_to_file(file_name, history.str(), first);
      n_written = histories.empty() ? 0 : histories[0].size();
      if (!keep_all_samples && n_written > 1)
        {
          for (auto &h : histories)
            h.erase(h.begin(), h.end() - 1);
          n_written = 1;
        }
    }
  } // namespace postprocess
} // namespace ndda
