// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checkpoints of a run, and runs resumed from them (doc/design.md,
// "Decisions"). A checkpoint holds what a run carries from step to step
// and cannot compute again: the scene's .prm text, the mesh with its
// cracks and the initial position of every vertex, the block models, the
// state vectors, the element matrices of each cell's last computation, the
// stresses, the contacts' memory, the step control and what has been
// written. A resumed run sets up everything else as any run does, on the
// initial geometry; what depends on when it was last built (the system and
// its factorization, the neighbour list) is built anew by both the run
// that writes a checkpoint and the run that reads it
// (rebuild_after_checkpoint()), so that the two go on identically.

#include <ndda/base/archive.h>
#include <ndda/base/atomic_file.h>
#include <ndda/simulator.h>

#include <filesystem>
#include <sstream>

namespace ndda
{
  namespace
  {
    const std::string checkpoint_name = "checkpoint.ndda";

    /// The size of the file @p name, 0 if there is none.
    std::uint64_t
    file_bytes(const std::string &name)
    {
      std::error_code error;
      const auto      n = std::filesystem::file_size(name, error);
      return error ? 0 : n;
    }
  } // namespace



  template <int dim>
  struct Simulator<dim>::ResumeState
  {
    /// The checkpoint file and its contents.
    std::string              file;
    std::string              data;
    std::unique_ptr<Archive> archive;
    /// The sizes of the statistics and measure-point files at the
    /// checkpoint.
    std::uint64_t statistics_bytes = 0, measure_bytes = 0;
  };



  template <int dim>
  std::unique_ptr<Simulator<dim>>
  Simulator<dim>::resume(const std::string &output_directory,
                         const MPI_Comm     communicator)
  {
    std::error_code error;
    AssertThrow(std::filesystem::is_directory(output_directory, error),
                ExcMessage("ndda --resume: '" + output_directory +
                           "' is not a directory. Give the output directory "
                           "of the run (output/<scene name>)."));
    std::string directory = output_directory;
    if (directory.back() != '/')
      directory += '/';
    auto state  = std::make_shared<ResumeState>();
    state->file = directory + checkpoint_name;
    AssertThrow(std::filesystem::exists(state->file, error),
                ExcMessage("ndda --resume: '" + output_directory +
                           "' holds no " + checkpoint_name +
                           ": the run wrote no checkpoint. Set "
                           "Output/Checkpoint interval to have them."));
    {
      std::ifstream      in(state->file, std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      AssertThrow(!in.bad() && !bytes.str().empty(),
                  ExcMessage("ndda --resume: cannot read '" + state->file +
                             "'."));
      state->data = bytes.str();
    }
    state->archive = std::make_unique<Archive>(state->data, state->file);
    Archive    &ar = *state->archive;
    std::string text, file_name;
    ar.section("parameters");
    ar &text &file_name;

    auto simulator = std::make_unique<Simulator<dim>>(parameters::Parameters(),
                                                      nullptr,
                                                      communicator);
    simulator->parameters.read(text, file_name, simulator->prm);
    simulator->parameters_from_file = true;
    simulator->parameter_text       = text;
    simulator->parameter_file_name  = file_name;
    // The run goes on where its checkpoint is, wherever that was.
    simulator->parameters.output.directory = directory;
    simulator->resume_state                = state;
    return simulator;
  }



  template <int dim>
  void
  Simulator<dim>::write_checkpoint()
  {
    AssertThrow(!parameter_text.empty(),
                ExcMessage("write_checkpoint(): a checkpoint holds the "
                           "scene's .prm file, and this scene was not read "
                           "from one (Simulator(parameter_file))."));
    SectionTimer::Scope scope(timer, "checkpoint");
    // The first process writes; every process sets up anew as a resumed
    // run would.
    if (writes_files())
      write_checkpoint_file();
    rebuild_after_checkpoint();
  }



  template <int dim>
  void
  Simulator<dim>::write_checkpoint_file()
  {
    const std::string &directory = parameters.output.directory;
    std::filesystem::create_directories(directory);
    // The files hold every row up to now; the checkpoint records their
    // lengths.
    write_statistics();
    AtomicFile file(directory + checkpoint_name);
    {
      Archive ar(file.stream());
      ar.section("parameters");
      ar &parameter_text &parameter_file_name;
      ar.section("mesh");
      ar &mesh &scene_half_height;

      ar.section("block models");
      std::vector<std::string> names;
      for (const auto &m : fem.models)
        names.push_back(m.first);
      std::vector<unsigned int> model_of_cell;
      for (const auto *model : fem.cell_model)
        for (unsigned int i = 0; i < fem.models.size(); ++i)
          if (fem.models[i].second.get() == model)
            model_of_cell.push_back(i);
      AssertDimension(model_of_cell.size(), fem.cell_model.size());
      ar &names &model_of_cell &fem.cell_auto;

      std::vector<Point<dim>> vertices = mesh.get_block_mesh().vertices;
      serialize_state(ar, vertices);
      ar.finish();
    }
    file.commit();
  }



  template <int dim>
  void
  Simulator<dim>::read_checkpoint_mesh()
  {
    Archive &ar = *resume_state->archive;
    ar.section("mesh");
    ar &mesh &scene_half_height;
  }



  template <int dim>
  void
  Simulator<dim>::read_checkpoint_models()
  {
    Archive &ar = *resume_state->archive;
    ar.section("block models");
    std::vector<std::string>  names;
    std::vector<unsigned int> model_of_cell;
    std::vector<bool>         cell_auto;
    ar &names &model_of_cell &cell_auto;
    AssertThrow(model_of_cell.size() == fem.cell_model.size() &&
                  cell_auto.size() == fem.cell_model.size(),
                ExcMessage("'" + resume_state->file +
                           "' is damaged: its block models do not fit its "
                           "mesh."));
    // The models in the run's order (the statistics list them so).
    fem.models.clear();
    std::vector<const kinematics::BlockKinematics *> models;
    for (const auto &name : names)
      models.push_back(fem.model(name));
    for (unsigned int c = 0; c < model_of_cell.size(); ++c)
      {
        AssertThrow(model_of_cell[c] < models.size(),
                    ExcMessage("'" + resume_state->file +
                               "' is damaged: a cell has no block model."));
        fem.cell_model[c] = models[model_of_cell[c]];
      }
    fem.cell_auto = cell_auto;
  }



  template <int dim>
  void
  Simulator<dim>::serialize_state(Archive                 &ar,
                                  std::vector<Point<dim>> &vertices)
  {
    ar.section("state");
    ar &vertices &time &step_number &displacement &kinematics
      .velocity &kinematics.inertia_force &kinematics.acceleration &kinematics
      .starting &inertia_correction &external_force &last_mean_velocity;
    ar &load_work &prescribed_work &viscous_work &initial_kinetic_energy
      &initial_strain_energy &initial_strain_energy_known;
    ar &n_matrix_rebuilds &max_increment &n_crack_events &n_cracked_edges
      &crack_limit_hit &contact_distances;
    ar.section("cells");
    ar &fem.element_cache &fem.frames &stresses &fem.bolts;
    ar.section("contacts");
    ar &contacts &detection;
    ar.section("step control");
    ar &step_controller &open_close;
    ar.section("kinematics and fracture");
    ar &automatic &fracture_check;

    ar.section("output");
    const std::string &directory = parameters.output.directory;
    statistics.serialize(ar, directory + "statistics");
    measure_points.serialize(ar, directory + "measure_points.txt");
    ar           &visualization;
    std::uint64_t statistics_bytes = file_bytes(directory + "statistics");
    std::uint64_t measure_bytes = file_bytes(directory + "measure_points.txt");
    ar &statistics_bytes &measure_bytes;
    if (ar.loading())
      {
        resume_state->statistics_bytes = statistics_bytes;
        resume_state->measure_bytes    = measure_bytes;
      }
    ar.section("end");
  }



  template <int dim>
  void
  Simulator<dim>::read_checkpoint_state()
  {
    std::vector<Point<dim>> vertices;
    serialize_state(*resume_state->archive, vertices);
    const unsigned int n_dofs = fem.dof_handler.n_dofs();
    AssertThrow(vertices.size() == mesh.get_block_mesh().vertices.size() &&
                  displacement.size() == n_dofs &&
                  kinematics.velocity.size() == n_dofs &&
                  kinematics.inertia_force.size() == n_dofs &&
                  external_force.size() == n_dofs,
                ExcMessage("'" + resume_state->file +
                           "' is damaged: its state does not fit its mesh."));
    mesh.set_vertices(vertices);
    rebuild_after_checkpoint();
    resume_state->archive.reset();
    resume_state->data = std::string();
  }



  template <int dim>
  void
  Simulator<dim>::rebuild_after_checkpoint()
  {
    // The system (reduced blocks' lines on the present geometry), the
    // fracture edges, the global matrices and the internal force.
    set_up_block_models(false);
    fem.linear_system.drop_factorization();
    if (parameters.contact.enabled)
      contacts.forget_neighbours();
  }



  template <int dim>
  void
  Simulator<dim>::continue_files()
  {
    const auto cut = [&](const std::string &name, const std::uint64_t bytes) {
      const std::string   file = parameters.output.directory + name;
      const std::uint64_t now  = file_bytes(file);
      if (now == bytes)
        return;
      AssertThrow(now > bytes,
                  ExcMessage("ndda --resume: '" + file + "' holds " +
                             std::to_string(now) + " bytes, fewer than the " +
                             std::to_string(bytes) +
                             " it held at the checkpoint: it was changed "
                             "since. Put it back, or run the scene anew."));
      // The rows the run wrote after its checkpoint are written again.
      std::filesystem::resize_file(file, bytes);
    };
    cut("statistics", resume_state->statistics_bytes);
    cut("measure_points.txt", resume_state->measure_bytes);
  }



  template std::unique_ptr<Simulator<2>>
  Simulator<2>::resume(const std::string &, const MPI_Comm);
  template void
  Simulator<2>::write_checkpoint();
  template void
  Simulator<2>::write_checkpoint_file();
  template void
  Simulator<2>::read_checkpoint_mesh();
  template void
  Simulator<2>::read_checkpoint_models();
  template void
  Simulator<2>::serialize_state(Archive &, std::vector<Point<2>> &);
  template void
  Simulator<2>::read_checkpoint_state();
  template void
  Simulator<2>::rebuild_after_checkpoint();
  template void
  Simulator<2>::continue_files();
} // namespace ndda
