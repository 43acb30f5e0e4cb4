// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <ndda/postprocess/visualization.h>
#include <ndda/simulator.h>

#include <fstream>

namespace ndda
{
  namespace postprocess
  {
    using namespace dealii;

    void
    VisualizationWriter::write_frame(
      const Simulator<2>                                      &simulator,
      const std::vector<std::shared_ptr<const Postprocessor>> &postprocessors)
    {
      const auto &output = simulator.get_parameters().output;
      // Nothing is written: no patches to build (they cost as much as a
      // time step of a small scene).
      if (!output.write_vtu && !output.write_hdf5)
        return;
      DataOut<2> data_out;
      Frame frame(data_out, output_number, output.write_vtu, output.directory);
      data_out.attach_dof_handler(simulator.get_dof_handler());
      for (const auto &postprocessor : postprocessors)
        postprocessor->add_fields(simulator, frame);
      data_out.build_patches(simulator.get_mapping(),
                             simulator.get_n_output_subdivisions());
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      data_out.set_flags(flags);

      const double      time   = simulator.get_time();
      const std::string number = Utilities::int_to_string(output_number, 5);
      if (output.write_vtu)
        {
          const std::string name = "solution-" + number + ".vtu";
          std::ofstream     vtu(output.directory + name);
          data_out.write_vtu(vtu);
          pvd_records.emplace_back(time, name);
          std::ofstream pvd(output.directory + "solution.pvd");
          DataOutBase::write_pvd_record(pvd, pvd_records);
        }
      if (output.write_hdf5)
        {
          const std::string          name = "solution-" + number + ".h5";
          DataOutBase::DataOutFilter filter(
            DataOutBase::DataOutFilterFlags(true, true));
          data_out.write_filtered_data(filter);
          data_out.write_hdf5_parallel(filter,
                                       output.directory + name,
                                       MPI_COMM_SELF);
          xdmf_entries.push_back(
            data_out.create_xdmf_entry(filter, name, time, MPI_COMM_SELF));
          data_out.write_xdmf_file(xdmf_entries,
                                   output.directory + "solution.xdmf",
                                   MPI_COMM_SELF);
        }
      ++output_number;
    }
  } // namespace postprocess
} // namespace ndda
