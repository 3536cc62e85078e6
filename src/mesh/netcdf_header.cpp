#include "mesh/netcdf_header.hpp"

#include "base/errors.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

namespace kiln
{
namespace internal
{
namespace // file-local: the reader of the classic format (netCDF User Guide, "File Format")
{
constexpr std::uint32_t tag_absent = 0, tag_dimension = 0x0A, tag_variable = 0x0B,
                        tag_attribute = 0x0C;
constexpr std::uint64_t unlimited = std::numeric_limits<std::uint64_t>::max();

/// Thrown inside the reader; turned into a NetcdfHeader by read_netcdf_header().
struct Stop
{
  NetcdfHeader::Kind kind;
  std::string problem;
};

class Reader
{
public:
  Reader(const unsigned char *bytes, const std::uint64_t size, const int version)
      : bytes_(bytes), size_(size), version_(version)
  {
  }

  std::uint64_t position() const { return pos_; }
  std::uint64_t remaining() const { return size_ - pos_; }

  std::uint64_t big_endian(const int n)
  {
    if (remaining() < static_cast<std::uint64_t>(n))
      throw Stop{NetcdfHeader::Kind::need_more, ""};
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i)
      v = (v << 8) | bytes_[pos_ + i];
    pos_ += n;
    return v;
  }
  std::uint32_t u32() { return static_cast<std::uint32_t>(big_endian(4)); }
  /// NON_NEG: 32 bits in CDF-1 and CDF-2, 64 bits in CDF-5.
  std::uint64_t non_neg()
  {
    const std::uint64_t v = big_endian(version_ == 5 ? 8 : 4);
    if (version_ != 5 && v > 0x7FFFFFFFULL)
      damaged("a count or length " + std::to_string(v) + " is negative");
    return v;
  }
  /// OFFSET: 32 bits in CDF-1, 64 bits otherwise.
  std::uint64_t offset() { return big_endian(version_ == 1 ? 4 : 8); }

  void skip(const std::uint64_t n)
  {
    if (remaining() < n)
      throw Stop{NetcdfHeader::Kind::need_more, ""};
    pos_ += n;
  }
  /// A name: its length, then its bytes padded to 4.
  void name()
  {
    const std::uint64_t length = non_neg();
    skip(padded(length));
  }
  /// A count of items: each takes at least 4 bytes of the header, so a count too large for
  /// the bytes given ends in need_more, never in a long loop.
  std::uint64_t count() { return non_neg(); }

  [[noreturn]] static void damaged(const std::string &problem)
  {
    throw Stop{NetcdfHeader::Kind::damaged, problem};
  }
  static std::uint64_t padded(const std::uint64_t n)
  {
    if (n > std::numeric_limits<std::uint64_t>::max() - 3)
      damaged("a length overflows");
    return (n + 3) / 4 * 4;
  }

private:
  const unsigned char *bytes_;
  std::uint64_t size_;
  int version_;
  std::uint64_t pos_ = 0;
};

/// Bytes per value of a netCDF external type; 0 for an unknown type.
std::uint64_t type_size(const std::uint32_t type, const int version)
{
  switch (type)
  {
  case 1: // byte
  case 2: // char
    return 1;
  case 3: // short
    return 2;
  case 4: // int
  case 5: // float
    return 4;
  case 6: // double
    return 8;
  default:
    break;
  }
  if (version != 5)
    return 0;
  switch (type)
  {
  case 7: // ubyte
    return 1;
  case 8: // ushort
    return 2;
  case 9: // uint
    return 4;
  case 10: // int64
  case 11: // uint64
    return 8;
  default:
    return 0;
  }
}

std::uint64_t saturating_product(const std::uint64_t a, const std::uint64_t b)
{
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
    return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}

std::uint64_t saturating_sum(const std::uint64_t a, const std::uint64_t b)
{
  return a > std::numeric_limits<std::uint64_t>::max() - b
             ? std::numeric_limits<std::uint64_t>::max()
             : a + b;
}

void read_attributes(Reader &r, const int version)
{
  const std::uint32_t tag = r.u32();
  const std::uint64_t n = r.count();
  if (tag == tag_absent && n == 0)
    return;
  if (tag != tag_attribute)
    Reader::damaged("an attribute list has the tag " + std::to_string(tag));
  for (std::uint64_t i = 0; i < n; ++i)
  {
    r.name();
    const std::uint32_t type = r.u32();
    const std::uint64_t size = type_size(type, version);
    if (size == 0)
      Reader::damaged("an attribute has the unknown type " + std::to_string(type));
    const std::uint64_t values = r.count();
    if (values > std::numeric_limits<std::uint64_t>::max() / 16)
      Reader::damaged("an attribute announces " + std::to_string(values) + " values");
    r.skip(Reader::padded(values * size));
  }
}

NetcdfHeader read_classic(const unsigned char *bytes, const std::uint64_t size, const int version)
{
  Reader r(bytes, size, version);
  r.skip(4);
  const std::uint64_t numrecs = version == 5 ? r.big_endian(8) : r.u32();
  const bool streaming = numrecs == (version == 5 ? unlimited : 0xFFFFFFFFULL);

  std::vector<std::uint64_t> dims;
  {
    const std::uint32_t tag = r.u32();
    const std::uint64_t n = r.count();
    if (!(tag == tag_absent && n == 0))
    {
      if (tag != tag_dimension)
        Reader::damaged("the dimension list has the tag " + std::to_string(tag));
      for (std::uint64_t i = 0; i < n; ++i)
      {
        r.name();
        dims.push_back(r.non_neg()); // 0: the record (unlimited) dimension
      }
    }
  }
  read_attributes(r, version);

  struct Variable
  {
    bool record;
    std::uint64_t begin, bytes_per_record, vsize;
  };
  std::vector<Variable> variables;
  {
    const std::uint32_t tag = r.u32();
    const std::uint64_t n = r.count();
    if (!(tag == tag_absent && n == 0))
    {
      if (tag != tag_variable)
        Reader::damaged("the variable list has the tag " + std::to_string(tag));
      for (std::uint64_t i = 0; i < n; ++i)
      {
        r.name();
        const std::uint64_t rank = r.count();
        Variable v{false, 0, 1, 0};
        for (std::uint64_t d = 0; d < rank; ++d)
        {
          const std::uint64_t id = version == 5 ? r.big_endian(8) : r.u32();
          if (id >= dims.size())
            Reader::damaged("variable " + std::to_string(i + 1) + " uses dimension " +
                            std::to_string(id) + " of " + std::to_string(dims.size()));
          if (dims[id] == 0 && d != 0)
            Reader::damaged("variable " + std::to_string(i + 1) +
                            " has the record dimension in a place other than first");
          if (dims[id] == 0)
            v.record = true;
          else
            v.bytes_per_record = saturating_product(v.bytes_per_record, dims[id]);
        }
        read_attributes(r, version);
        const std::uint32_t type = r.u32();
        const std::uint64_t value_bytes = type_size(type, version);
        if (value_bytes == 0)
          Reader::damaged("variable " + std::to_string(i + 1) + " has the unknown type " +
                          std::to_string(type));
        v.bytes_per_record = saturating_product(v.bytes_per_record, value_bytes);
        v.vsize = r.non_neg();
        v.begin = r.offset();
        if (v.begin < 4)
          Reader::damaged("variable " + std::to_string(i + 1) + " starts inside the header");
        variables.push_back(v);
      }
    }
  }

  NetcdfHeader h;
  h.kind = NetcdfHeader::Kind::classic;
  h.version = version;
  h.data_end = r.position();
  std::uint64_t record_size = 0;
  int n_record = 0;
  for (const Variable &v : variables)
    if (v.record)
    {
      record_size = saturating_sum(record_size, v.vsize);
      ++n_record;
    }
  for (const Variable &v : variables)
  {
    if (v.begin < r.position())
      Reader::damaged("a variable's data start at byte " + std::to_string(v.begin) +
                      ", inside the header (which ends at byte " + std::to_string(r.position()) +
                      ")");
    std::uint64_t end = saturating_sum(v.begin, v.bytes_per_record);
    if (v.record)
    {
      if (streaming || numrecs == 0)
        continue;
      const std::uint64_t stride = n_record == 1 ? v.bytes_per_record : record_size;
      end = saturating_sum(saturating_sum(v.begin, saturating_product(numrecs - 1, stride)),
                           v.bytes_per_record);
    }
    h.data_end = std::max(h.data_end, end);
  }
  return h;
}
} // namespace
} // namespace internal

NetcdfHeader read_netcdf_header(const unsigned char *bytes, const std::uint64_t size,
                                const std::uint64_t file_size)
{
  if (size < 4)
  {
    NetcdfHeader h;
    h.kind = NetcdfHeader::Kind::need_more;
    return h;
  }
  if (!(bytes[0] == 'C' && bytes[1] == 'D' && bytes[2] == 'F' &&
        (bytes[3] == 1 || bytes[3] == 2 || bytes[3] == 5)))
    return NetcdfHeader{};
  try
  {
    return internal::read_classic(bytes, std::min(size, file_size), bytes[3]);
  }
  catch (const internal::Stop &stop)
  {
    NetcdfHeader h;
    h.kind = stop.kind;
    h.version = bytes[3];
    h.problem = stop.problem;
    return h;
  }
}

void check_netcdf_file(const std::string &path)
{
  std::error_code error;
  const std::uint64_t file_size = std::filesystem::file_size(path, error);
  if (error)
    return; // the caller reports a file it cannot open
  std::ifstream file(path, std::ios::binary);
  std::vector<unsigned char> head;
  // A header is a few kB; one larger than max_header is damaged (a bogus count).
  constexpr std::uint64_t max_header = 64ULL << 20;
  std::uint64_t wanted = std::min<std::uint64_t>(file_size, 64 * 1024);
  NetcdfHeader h;
  while (true)
  {
    head.resize(wanted);
    file.seekg(0);
    file.read(reinterpret_cast<char *>(head.data()), static_cast<std::streamsize>(wanted));
    if (!file)
      return;
    h = read_netcdf_header(head.data(), wanted, file_size);
    if (h.kind != NetcdfHeader::Kind::need_more || wanted == file_size || wanted >= max_header)
      break;
    wanted = std::min<std::uint64_t>({file_size, 2 * wanted, max_header});
  }
  KILN_CHECK_INPUT(h.kind != NetcdfHeader::Kind::need_more || wanted < file_size, path,
                   "the file is truncated: it ends (at byte "
                       << file_size
                       << ") inside its netCDF header; the copy or export was cut short (or the "
                          "header is damaged): copy or export the mesh again");
  KILN_CHECK_INPUT(h.kind != NetcdfHeader::Kind::need_more, path,
                   "its netCDF header is damaged (it runs past " << max_header
                                                                 << " bytes); it is not a "
                                                                    "readable Exodus II mesh: "
                                                                    "export the mesh again");
  KILN_CHECK_INPUT(h.kind != NetcdfHeader::Kind::damaged, path,
                   "its netCDF header is damaged (" << h.problem
                                                    << "); it is not a readable Exodus II "
                                                       "mesh: export the mesh again");
  KILN_CHECK_INPUT(h.kind != NetcdfHeader::Kind::classic || h.data_end <= file_size, path,
                   "the file is truncated: it holds "
                       << file_size << " bytes but its header places data up to byte " << h.data_end
                       << "; the copy or export was cut short: copy or export the mesh again");
}
} // namespace kiln
