// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>

#include <ndda/base/archive.h>

#include <cstring>

namespace ndda
{
  namespace
  {
    /// The first bytes of every archive, and the version of the format:
    /// raised whenever a class changes what its serialize() lists.
    const std::string  magic          = "ndda archive\n";
    const std::int32_t format_version = 6;
    /// Written as bytes: reads back as this only on a machine of the same
    /// byte order.
    const std::uint32_t byte_order = 0x01020304;

    /// Add @p n bytes at @p data to the FNV-1a hash @p hash.
    std::uint64_t
    fnv1a(std::uint64_t hash, const char *data, const std::size_t n)
    {
      for (std::size_t i = 0; i < n; ++i)
        hash = (hash ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
      return hash;
    }
  } // namespace



  Archive::Archive(std::ostream &out)
    : out(&out)
  {
    out.write(magic.data(), magic.size());
    checksum = fnv1a(checksum, magic.data(), magic.size());
    std::int32_t           version = format_version;
    std::uint32_t          order   = byte_order;
    double                 one     = 1.;
    *this &version &order &one;
  }



  Archive::Archive(const std::string &data, const std::string &name)
    : data(&data)
    , name(name)
  {
    AssertThrow(data.compare(0, magic.size(), magic) == 0,
                dealii::ExcMessage("'" + name +
                                   "' is not an ndda checkpoint (it does not "
                                   "begin as one)."));
    std::uint64_t stored = 0;
    AssertThrow(data.size() >= magic.size() + sizeof(stored),
                dealii::ExcMessage("'" + name + "' is truncated."));
    std::memcpy(&stored,
                data.data() + data.size() - sizeof(stored),
                sizeof(stored));
    AssertThrow(stored ==
                  fnv1a(checksum, data.data(), data.size() - sizeof(stored)),
                dealii::ExcMessage(
                  "'" + name +
                  "' is damaged: its checksum does not match its contents "
                  "(a truncated or changed file). It cannot be resumed."));
    position                       = magic.size();
    std::int32_t           version = 0;
    std::uint32_t          order   = 0;
    double                 one     = 0;
    *this &version &order &one;
    AssertThrow(version == format_version,
                dealii::ExcMessage("'" + name + "' is a checkpoint of format " +
                                   std::to_string(version) +
                                   "; this ndda reads format " +
                                   std::to_string(format_version) +
                                   ". Resume it with the ndda that wrote it."));
    AssertThrow(order == byte_order && one == 1.,
                dealii::ExcMessage("'" + name +
                                   "' was written on a machine with another "
                                   "byte order or number format."));
  }



  void
  Archive::section(const std::string &section_name)
  {
    std::string s = section_name;
    *this      &s;
    AssertThrow(s == section_name,
                dealii::ExcMessage("'" + name +
                                   "' is damaged or was written by another "
                                   "version of ndda: section '" +
                                   section_name + "' expected after section '" +
                                   last_section + "'."));
    last_section = section_name;
  }



  std::size_t
  Archive::remaining() const
  {
    return loading() ? data->size() - sizeof(checksum) - position : 0;
  }



  void
  Archive::finish()
  {
    if (loading())
      return;
    const std::uint64_t hash = checksum;
    out->write(reinterpret_cast<const char *>(&hash), sizeof(hash));
    AssertThrow(out->good(),
                dealii::ExcMessage("Cannot write a checkpoint: is the disk "
                                   "full?"));
  }



  void
  Archive::bytes(void *value, const std::size_t n)
  {
    if (!loading())
      {
        out->write(static_cast<const char *>(value), n);
        checksum = fnv1a(checksum, static_cast<const char *>(value), n);
        AssertThrow(out->good(),
                    dealii::ExcMessage("Cannot write a checkpoint (" +
                                       std::to_string(n) +
                                       " bytes): is the disk full?"));
        return;
      }
    AssertThrow(n <= remaining(),
                dealii::ExcMessage(
                  "'" + name + "' ends too early (in section '" + last_section +
                  "'): the file is truncated or damaged."));
    std::memcpy(value, data->data() + position, n);
    position += n;
  }



  std::size_t
  Archive::size(const std::size_t n, const std::size_t element_size)
  {
    std::uint64_t stored = n;
    bytes(&stored, sizeof(stored));
    AssertThrow(!loading() || element_size == 0 ||
                  stored <= remaining() / element_size,
                dealii::ExcMessage("'" + name + "' is damaged (in section '" +
                                   last_section + "': a size of " +
                                   std::to_string(stored) +
                                   " that the rest of the file cannot hold)."));
    return stored;
  }



  void
  Archive::check_writing() const
  {
    Assert(!loading(),
           dealii::ExcMessage("A value that cannot change was given to "
                              "a reading archive."));
  }
} // namespace ndda
