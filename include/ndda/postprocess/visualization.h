// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_visualization_h
#define ndda_postprocess_visualization_h

#include <deal.II/base/data_out_base.h>

#include <ndda/postprocess/postprocessor.h>

#include <string>
#include <utility>
#include <vector>

namespace ndda
{
  namespace postprocess
  {
    /**
     * Writes the output frames of a run: at every output time one
     * solution-NNNNN.vtu (and .h5) with the fields of the selected
     * postprocessors, on the present (deformed) geometry, and the
     * collections solution.pvd and solution.xdmf that ParaView opens.
     *
     * @ingroup postprocess
     */
    class VisualizationWriter
    {
    public:
      /**
       * Write the frame of the present state of @p simulator with the
       * fields of @p postprocessors, in Output/Directory (VTU and
       * HDF5, as Output/Write vtu and Write hdf5 ask; nothing if neither).
       */
      void
      write_frame(const Simulator<2> &simulator,
                  const std::vector<std::shared_ptr<const Postprocessor>>
                    &postprocessors);

      /** Frames written so far. */
      unsigned int
      n_frames() const
      {
        return output_number;
      }

      /** Write the frames written so far (number, collections) to a
       * checkpoint or read them (Archive). */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &output_number &pvd_records &xdmf_entries;
      }

    private:
      unsigned int                                output_number = 0;
      std::vector<std::pair<double, std::string>> pvd_records;
      std::vector<dealii::XDMFEntry>              xdmf_entries;
    };
  } // namespace postprocess
} // namespace ndda

#endif
