// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_postprocessor_h
#define ndda_postprocess_postprocessor_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/vector.h>

#include <ndda/base/plugin_registry.h>
#include <ndda/postprocess/statistics_table.h>

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DataOut;
}

namespace ndda
{
  template <int dim>
  class Simulator;

  /**
   * What a run reports: VTU fields, groups of statistics columns, files of
   * their own, each a plugin.
   *
   * @ingroup postprocess
   */
  namespace postprocess
  {
    using dealii::ParameterHandler;

    /**
     * The fields of one output frame: a DataOut with the DoFHandler
     * attached, and storage for the cell vectors the postprocessors add
     * (DataOut keeps references to them until the frame is written).
     */
    struct Frame
    {
      Frame(dealii::DataOut<2, 2> &data_out,
            const unsigned int     number,
            const bool             write_vtu,
            const std::string     &directory)
        : data_out(data_out)
        , number(number)
        , write_vtu(write_vtu)
        , directory(directory)
      {}

      /** Release the data before what the frame keeps alive goes. */
      ~Frame();

      dealii::DataOut<2, 2> &data_out;
      /// Output number of the frame (solution-NNNNN).
      unsigned int number;
      /// Whether VTU files are written (files beside them, such as the
      /// crack faces, are written only then).
      bool write_vtu;
      /// Output directory, ending in '/'.
      std::string directory;

      /** A cell vector that lives as long as the frame. */
      dealii::Vector<double> &
      new_cell_vector(const unsigned int n_cells)
      {
        storage.emplace_back(n_cells);
        return storage.back();
      }

      /**
       * Keep @p object (a DoFHandler of a field and its vectors) as long
       * as the frame.
       */
      template <class T>
      T &
      keep(std::unique_ptr<T> object)
      {
        T &kept = *object;
        objects.emplace_back(std::move(object));
        return kept;
      }

    private:
      std::deque<dealii::Vector<double>> storage;
      std::deque<std::shared_ptr<void>>  objects;
    };

    /**
     * Interface of a postprocessor (ASPECT's Postprocess::Interface): it
     * reads the simulator's state (read-only) and adds VTU fields to an
     * output frame, columns to the statistics table after each step, or
     * both. Postprocessors hold no state of their own between calls, so
     * that one selection may serve several simulators.
     *
     * A postprocessor is a plugin (NDDA_REGISTER_PLUGIN with this
     * interface): `set List of postprocessors = a, b` in
     * `subsection Postprocess` selects them, in that order (the order of
     * the VTU fields and statistics columns); each reads its own entries
     * from `subsection Postprocess / subsection <name>`.
     */
    class Postprocessor
    {
    public:
      virtual ~Postprocessor() = default;

      /**
       * Declare the postprocessor's parameters (its subsection is
       * entered). The default declares none; a postprocessor with
       * parameters hides it with its own.
       */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the postprocessor's parameters (its subsection is entered). */
      virtual void
      parse_parameters(ParameterHandler &prm);

      /** Add this postprocessor's fields to an output frame. Default: none. */
      virtual void
      add_fields(const Simulator<2> &simulator, Frame &frame) const;

      /**
       * Add this postprocessor's columns for the step just done to
       * @p statistics. Default: none.
       */
      virtual void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const;

      /** For messages (PluginRegistry). */
      static const char *
      plugin_kind()
      {
        return "postprocessor";
      }

      static const char *
      plugin_kinds()
      {
        return "postprocessors";
      }

      static const char *
      selection_entry()
      {
        return "Postprocess/List of postprocessors";
      }

      /** Keep the built-in postprocessors in every program. */
      static void
      link_builtin_plugins();
    };

    /** The registry of postprocessors. */
    using PostprocessorRegistry = PluginRegistry<Postprocessor>;

    /**
     * Add @p value to column @p column of @p statistics, written in
     * scientific notation with six digits.
     */
    void
    add_scientific(StatisticsTable   &statistics,
                   const std::string &column,
                   const double       value);

  } // namespace postprocess

  namespace parameters
  {
    using dealii::ParameterHandler;

    /** `subsection Postprocess`: the selected postprocessors. */
    struct Postprocess
    {
      /// The selected postprocessors, in the order of the list, with
      /// their parameters read; stateless, so they may be shared.
      std::vector<std::shared_ptr<const postprocess::Postprocessor>>
                               postprocessors;
      std::vector<std::string> names;

      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace ndda

#endif
