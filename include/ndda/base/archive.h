// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_archive_h
#define ndda_base_archive_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace ndda
{
  /**
   * The binary archive of a checkpoint (Simulator::write_checkpoint()).
   * One class writes and reads, so that a class lists the members of its
   * state once, in a member
   *
   *   template <class Archive> void serialize(Archive &ar)
   *   { ar & a & b & c; }
   *
   * that writes them to a writing archive and reads them from a reading
   * one (loading() tells which, for what must be rebuilt after reading).
   * Numbers are stored as their bytes, so a double comes back bit for bit;
   * a checkpoint is read by the build that wrote it, on the same kind of
   * machine (the header checks the byte order and the format version).
   * Containers are stored with their sizes, and a size that the rest of the
   * file cannot hold is refused. section() writes a name that reading
   * checks, so that a damaged file or one from another version is refused
   * with the place where it goes wrong.
   *
   * @ingroup base
   */
  class Archive
  {
  public:
    /** An archive that writes to @p out. */
    explicit Archive(std::ostream &out);

    /** An archive that reads @p data, the contents of the file @p name
     * (kept by reference: it must outlive the archive). */
    Archive(const std::string &data, const std::string &name);

    /** Whether this archive reads. */
    bool
    loading() const
    {
      return data != nullptr;
    }

    /** Write or read @p value. */
    template <typename T>
    Archive &
    operator&(T &value)
    {
      io(value);
      return *this;
    }

    /** Write @p value (a writing archive only). */
    template <typename T>
    Archive &
    operator&(const T &value)
    {
      check_writing();
      io(const_cast<T &>(value));
      return *this;
    }

    /** Write the name of the section that follows, or check it. */
    void
    section(const std::string &name);

    /** The bytes not read yet (a reading archive). */
    std::size_t
    remaining() const;

    /**
     * A writing archive: append the checksum of everything written (the
     * last call). A reading archive checks it when it is made, so that a
     * file changed in any byte is refused before anything is read.
     */
    void
    finish();

  private:
    /// Whether T has a member serialize(Archive &).
    template <typename T, typename = void>
    struct has_serialize : std::false_type
    {};
    template <typename T>
    struct has_serialize<T,
                         std::void_t<decltype(std::declval<T &>().serialize(
                           std::declval<Archive &>()))>> : std::true_type
    {};
    /// Whether T has deal.II's serialize(Archive &, unsigned int).
    template <typename T, typename = void>
    struct has_versioned_serialize : std::false_type
    {};
    template <typename T>
    struct has_versioned_serialize<
      T,
      std::void_t<
        decltype(std::declval<T &>().serialize(std::declval<Archive &>(), 0u))>>
      : std::true_type
    {};

    /** Write or read @p n bytes at @p data. */
    void
    bytes(void *data, const std::size_t n);

    /** A container size: written, or read and checked against what is
     * left of the file for elements of at least @p element_size bytes. */
    std::size_t
    size(const std::size_t n, const std::size_t element_size);

    void
    check_writing() const;

    /// Types stored as their bytes: those without padding, whose bytes
    /// are their value (a struct's padding would be written as whatever
    /// memory held, and two equal states would differ as files).
    template <typename T>
    struct is_plain
      : std::bool_constant<std::is_arithmetic_v<T> || std::is_enum_v<T>>
    {};
    template <int rank, int dim>
    struct is_plain<dealii::Tensor<rank, dim, double>> : std::true_type
    {};
    template <int dim>
    struct is_plain<dealii::Point<dim, double>> : std::true_type
    {};
    template <int rank, int dim>
    struct is_plain<dealii::SymmetricTensor<rank, dim, double>> : std::true_type
    {};

    template <typename T>
    void
    io(T &value)
    {
      if constexpr (has_serialize<T>::value)
        value.serialize(*this);
      else if constexpr (has_versioned_serialize<T>::value)
        value.serialize(*this, 0u);
      else
        {
          static_assert(is_plain<T>::value,
                        "Archive: give this type a member serialize() "
                        "that lists its members.");
          static_assert(std::is_trivially_copyable_v<T>);
          bytes(&value, sizeof(T));
        }
    }

    void
    io(std::string &s)
    {
      s.resize(size(s.size(), 1));
      if (!s.empty())
        bytes(s.data(), s.size());
    }

    template <typename T>
    void
    io(std::vector<T> &v)
    {
      if constexpr (std::is_same_v<T, bool>)
        {
          std::vector<std::uint8_t> b(v.begin(), v.end());
          io(b);
          v.assign(b.begin(), b.end());
        }
      else
        {
          v.resize(size(v.size(), is_plain<T>::value ? sizeof(T) : 1));
          if constexpr (is_plain<T>::value)
            {
              if (!v.empty())
                bytes(v.data(), v.size() * sizeof(T));
            }
          else
            for (auto &x : v)
              io(x);
        }
    }

    template <typename T, std::size_t N>
    void
    io(std::array<T, N> &a)
    {
      for (auto &x : a)
        io(x);
    }

    template <typename A, typename B>
    void
    io(std::pair<A, B> &p)
    {
      io(p.first);
      io(p.second);
    }

    template <typename... Ts>
    void
    io(std::tuple<Ts...> &t)
    {
      std::apply([this](auto &...x) { (io(x), ...); }, t);
    }

    template <typename T>
    void
    io(std::optional<T> &o)
    {
      bool present = o.has_value();
      io(present);
      if (loading())
        {
          if (present)
            o.emplace();
          else
            o.reset();
        }
      if (present)
        io(*o);
    }

    template <typename K, typename V>
    void
    io(std::map<K, V> &m)
    {
      std::vector<std::pair<K, V>> entries(m.begin(), m.end());
      io(entries);
      if (loading())
        m = std::map<K, V>(entries.begin(), entries.end());
    }

    // A tensor is its components, contiguous.
    template <int rank, int dim>
    void
    io(dealii::Tensor<rank, dim, double> &t)
    {
      static_assert(sizeof(t) == t.n_independent_components * sizeof(double));
      bytes(&t, sizeof(t));
    }

    template <int dim>
    void
    io(dealii::Point<dim, double> &p)
    {
      io(static_cast<dealii::Tensor<1, dim, double> &>(p));
    }

    template <int rank, int dim>
    void
    io(dealii::SymmetricTensor<rank, dim, double> &t)
    {
      static_assert(sizeof(t) == t.n_independent_components * sizeof(double));
      bytes(&t, sizeof(t));
    }

    void
    io(dealii::Vector<double> &v)
    {
      const std::size_t n = size(v.size(), sizeof(double));
      if (loading())
        v.reinit(n);
      if (v.size() > 0)
        bytes(v.data(), v.size() * sizeof(double));
    }

    void
    io(dealii::FullMatrix<double> &m)
    {
      std::size_t rows = size(m.m(), 0), columns = size(m.n(), 0);
      if (loading())
        m.reinit(rows, columns);
      if (rows * columns > 0)
        bytes(&m(0, 0), rows * columns * sizeof(double));
    }

    std::ostream      *out  = nullptr;
    const std::string *data = nullptr;
    std::string        name;
    std::size_t        position = 0;
    std::string        last_section;
    /// FNV-1a hash of the bytes written.
    std::uint64_t checksum = 14695981039346656037ull;
  };
} // namespace ndda

#endif
