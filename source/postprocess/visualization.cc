// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <ndda/base/atomic_file.h>
#include <ndda/parallel/shared_mesh.h>
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
      // On several processes each writes the patches of the cells it owns
      // (a range of active cell indices of the shared triangulation,
      // parallel/shared_mesh.h: DataOut visits the locally owned cells),
      // and the first process the records that name the pieces.
      const MPI_Comm     communicator = simulator.get_communicator();
      const unsigned int n_pieces =
        Utilities::MPI::job_supports_mpi() ?
          Utilities::MPI::n_mpi_processes(communicator) :
          1;
      const unsigned int piece =
        n_pieces > 1 ? Utilities::MPI::this_mpi_process(communicator) : 0;
      AssertThrow(n_pieces == 1 ||
                    is_shared(simulator.get_dof_handler().get_triangulation()),
                  ExcInternalError());
      for (const auto &postprocessor : postprocessors)
        postprocessor->add_fields(simulator, frame);
      data_out.build_patches(simulator.get_mapping(),
                             simulator.get_n_output_subdivisions());
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      data_out.set_flags(flags);

      const double      time   = simulator.get_time();
      const std::string number = Utilities::int_to_string(output_number, 5);
      if (output.write_vtu && n_pieces > 1)
        {
          const auto piece_name = [&](const unsigned int p) {
            return "solution-" + number + "." +
                   Utilities::int_to_string(p,
                                            Utilities::needed_digits(n_pieces -
                                                                     1)) +
                   ".vtu";
          };
          AtomicFile vtu(output.directory + piece_name(piece));
          data_out.write_vtu(vtu.stream());
          vtu.commit();
          // The record after every piece is there.
          MPI_Barrier(communicator);
          if (simulator.writes_files())
            {
              std::vector<std::string> pieces;
              for (unsigned int p = 0; p < n_pieces; ++p)
                pieces.push_back(piece_name(p));
              const std::string name = "solution-" + number + ".pvtu";
              AtomicFile        pvtu(output.directory + name);
              data_out.write_pvtu_record(pvtu.stream(), pieces);
              pvtu.commit();
              pvd_records.emplace_back(time, name);
              AtomicFile pvd(output.directory + "solution.pvd");
              DataOutBase::write_pvd_record(pvd.stream(), pvd_records);
              pvd.commit();
            }
        }
      else if (output.write_vtu)
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
          // One file from all processes (parallel HDF5), collectively.
          const MPI_Comm hdf5_communicator =
            n_pieces > 1 ? communicator : MPI_COMM_SELF;
          data_out.write_hdf5_parallel(filter,
                                       output.directory + name + ".tmp",
                                       hdf5_communicator);
          if (simulator.writes_files())
            written(output.directory + name);
          xdmf_entries.push_back(
            data_out.create_xdmf_entry(filter, name, time, hdf5_communicator));
          data_out.write_xdmf_file(xdmf_entries,
                                   output.directory + "solution.xdmf.tmp",
                                   hdf5_communicator);
          if (simulator.writes_files())
            written(output.directory + "solution.xdmf");
        }
      ++output_number;
    }
  } // namespace postprocess
} // namespace ndda
