// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_output_parameters_h
#define ndda_postprocess_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace ndda
{
  /**
   * The parameters that postprocess/ reads besides its plugins:
   * subsection Output.
   *
   * @ingroup parameters
   */
  namespace parameters
  {
    using dealii::ParameterHandler;
    using dealii::Point;

    /** subsection Output */
    struct Output
    {
      std::string           directory;
      double                interval;
      bool                  write_vtu;
      bool                  write_hdf5;
      std::vector<Point<2>> measure_points;
      double                progress_interval;
      /// Simulated time between checkpoints (s); 0: none.
      double checkpoint_interval;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &scene_name);
    };

  } // namespace parameters
} // namespace ndda

#endif
