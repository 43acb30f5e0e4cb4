// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <ndda/base/atomic_file.h>
#include <ndda/postprocess/visualization.h>
#include <ndda/simulator.h>

#include <cstdio>
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
          // Each file appears complete or not at all (AtomicFile): the
          // frame before the collection that names it.
          AtomicFile vtu(output.directory + name);
          data_out.write_vtu(vtu.stream());
          vtu.commit();
          pvd_records.emplace_back(time, name);
          AtomicFile pvd(output.directory + "solution.pvd");
          DataOutBase::write_pvd_record(pvd.stream(), pvd_records);
          pvd.commit();
        }
      if (output.write_hdf5)
        {
          const std::string          name = "solution-" + number + ".h5";
          DataOutBase::DataOutFilter filter(
            DataOutBase::DataOutFilterFlags(true, true));
          data_out.write_filtered_data(filter);
          // Written under temporary names and renamed, as AtomicFile does.
          const auto written = [](const std::string &file) {
            AssertThrow(std::rename((file + ".tmp").c_str(), file.c_str()) == 0,
                        ExcMessage("Cannot rename " + file + ".tmp to " +
                                   file));
          };
          data_out.write_hdf5_parallel(filter,
                                       output.directory + name + ".tmp",
                                       MPI_COMM_SELF);
          written(output.directory + name);
          xdmf_entries.push_back(
            data_out.create_xdmf_entry(filter, name, time, MPI_COMM_SELF));
          data_out.write_xdmf_file(xdmf_entries,
                                   output.directory + "solution.xdmf.tmp",
                                   MPI_COMM_SELF);
          written(output.directory + "solution.xdmf");
        }
      ++output_number;
    }
  } // namespace postprocess
} // namespace ndda
