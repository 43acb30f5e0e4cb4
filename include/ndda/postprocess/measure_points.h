// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_measure_points_h
#define ndda_postprocess_measure_points_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe.h>

#include <deal.II/lac/vector.h>

#include <ndda/mesh/crackable_mesh.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/loads.h>
#include <ndda/physics/stress_field.h>

#include <string>
#include <vector>

namespace ndda
{
  /**
   * One value of a measure point at one time.
   */
  struct MeasureSample
  {
    double                        time;
    dealii::Tensor<1, 2>          displacement;
    dealii::Tensor<1, 2>          velocity;
    dealii::SymmetricTensor<2, 2> stress;

    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar &time &displacement &velocity &stress;
    }
  };

  namespace postprocess
  {
    /**
     * The measure points of a scene (Output/Measure points): material
     * points whose displacement, velocity and cell stress are recorded
     * after every step and written to measure_points.txt.
     *
     * The file is the history: write() appends the samples taken since
     * the last write and then forgets all but the last sample of every
     * point, so that a long run keeps its memory flat (a sample is 64
     * bytes a point a step, 6.4 MB a point over 1e5 steps). A program that
     * wants the whole history in memory asks for it with keep_all().
     */
    class MeasurePoints
    {
    public:
      /**
       * Locate @p points in @p mesh (on its present geometry; throws
       * naming Output/Measure points for a point outside every block).
       * With @p keep_histories (after a crack) the recorded samples stay.
       */
      void
      setup(const CrackableMesh            &mesh,
            const dealii::FiniteElement<2> &fe,
            const DofMap                   &dof_map,
            const std::vector<Point<2>>    &points,
            const bool                      keep_histories);

      /** Record a sample of every point at time @p time. */
      void
      record(const double                  time,
             const dealii::Vector<double> &displacement,
             const dealii::Vector<double> &velocity,
             const StressField            &stresses);

      /** Keep every sample in memory (get_histories()), not only those
       * not yet written and the last one. */
      void
      keep_all()
      {
        keep_all_samples = true;
      }

      /** Whether no sample has been recorded yet (and there are points). */
      bool
      waiting_for_first_sample() const
      {
        return !histories.empty() && histories[0].empty();
      }

      /**
       * The samples, one vector per point: every sample with keep_all(),
       * otherwise the last one written and those taken since (the last
       * sample is always back()).
       */
      const std::vector<std::vector<MeasureSample>> &
      get_histories() const
      {
        return histories;
      }

      /**
       * Write the samples to the text file @p file_name: the whole file
       * the first time (or for another file), after that only the samples
       * taken since, appended. Then forget the written samples but the
       * last (unless keep_all()).
       */
      void
      write(const std::string &file_name);

      /**
       * Write the samples and what has been written to a checkpoint, or
       * read them (Archive); the file is @p file_name now (the output
       * directory may have another name when the run resumes).
       */
      template <class Archive>
      void
      serialize(Archive &ar, const std::string &file_name)
      {
        bool                      written = !written_file.empty();
        ar &histories &n_written &written;
        if (ar.loading())
          written_file = written ? file_name : "";
      }

    private:
      std::vector<Point<2>>                   points;
      std::vector<PointEvaluator>             evaluators;
      std::vector<std::vector<MeasureSample>> histories;
      bool                                    keep_all_samples = false;
      /// The file written last and the samples of histories in it.
      std::string  written_file;
      unsigned int n_written = 0;
    };
  } // namespace postprocess
} // namespace ndda

#endif
