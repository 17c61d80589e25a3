#ifndef fgimpact_tests_vtu_reader_h
#define fgimpact_tests_vtu_reader_h

// Reads back what users open in ParaView: the data arrays of a VTU piece
// written with Output/VTU compression = none (raw appended binary data, or
// deal.II's base64 zlib stored blocks), independently of the library that
// wrote it.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fgimpact_tests
{
  /// The whole text of a file.
  inline std::string
  file_text(const std::string &file)
  {
    std::ifstream     in(file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    AssertThrow(in, dealii::ExcMessage("cannot read " + file));
    return buffer.str();
  }

  /// The float32 values of a DataArray with format="appended" (what
  /// Output/VTU compression = none writes): its offset="N" attribute
  /// counts from the byte after the '_' that opens <AppendedData
  /// encoding="raw">, where a UInt64 byte count precedes the values.
  inline std::vector<float>
  decode_appended(const std::string &text, const std::size_t tag)
  {
    const auto at     = text.find("offset=\"", tag) + 8;
    const auto offset = std::stoull(text.substr(at, text.find('"', at) - at));
    const auto start  = text.find('_', text.find("<AppendedData")) + 1;
    std::uint64_t n   = 0;
    std::memcpy(&n, text.data() + start + offset, sizeof(n));
    std::vector<float> values(n / sizeof(float));
    std::memcpy(values.data(), text.data() + start + offset + sizeof(n), n);
    return values;
  }

  /// The float32 values of the DataArray whose tag starts at position
  /// `tag` of text: appended raw data, or deal.II's base64 zlib body.
  inline std::vector<float>
  decode_array(const std::string &text, const std::size_t tag)
  {
    const auto tag_end = text.find('>', tag);
    if (text.substr(tag, tag_end - tag).find("format=\"appended\"") !=
        std::string::npos)
      return decode_appended(text, tag);
    const auto  begin = text.find('>', tag) + 1;
    const auto  end   = text.find("</DataArray>", begin);
    std::string body  = text.substr(begin, end - begin);
    body.erase(std::remove_if(body.begin(), body.end(), ::isspace), body.end());
    // A 16-byte header (4 uint32, its own base64 group), then the zlib
    // stream: 2 header bytes, stored blocks (1 flag byte, LEN, NLEN, data).
    const std::vector<unsigned char> z =
      dealii::Utilities::decode_base64(body.substr(24));
    std::vector<unsigned char> raw;
    std::size_t                i = 2;
    for (bool last = false; !last && i + 5 <= z.size();)
      {
        AssertThrow((z[i] & 6) == 0,
                    dealii::ExcMessage("not a stored zlib block"));
        last                  = z[i] & 1;
        const std::size_t len = z[i + 1] | (z[i + 2] << 8);
        raw.insert(raw.end(), z.begin() + i + 5, z.begin() + i + 5 + len);
        i += 5 + len;
      }
    std::vector<float> values(raw.size() / sizeof(float));
    std::memcpy(values.data(), raw.data(), raw.size());
    return values;
  }

  /// The float32 values of the DataArray `name` of a VTU file.
  inline std::vector<float>
  read_array(const std::string &file, const std::string &name)
  {
    const std::string text = file_text(file);
    const auto        tag  = text.find("Name=\"" + name + "\"");
    AssertThrow(tag != std::string::npos,
                dealii::ExcMessage(name + " not in " + file));
    return decode_array(text, tag);
  }

  /// The numbers of an ASCII DataArray of a VTU file's text (the sphere
  /// and contact files): the one named `name`, or the <Points> array if
  /// name is empty.
  inline std::vector<double>
  ascii_array(const std::string &text, const std::string &name)
  {
    const auto tag = name.empty() ?
                       text.find("<DataArray", text.find("<Points>")) :
                       text.find("Name=\"" + name + "\"");
    AssertThrow(tag != std::string::npos,
                dealii::ExcMessage("no array " + name));
    const auto          begin = text.find('>', tag) + 1;
    const auto          end   = text.find("</DataArray>", begin);
    std::istringstream  in(text.substr(begin, end - begin));
    std::vector<double> values;
    for (double x; in >> x;)
      values.push_back(x);
    return values;
  }

  /// The point coordinates (x, y, z per point) of a VTU file: the first
  /// DataArray of <Points>, which has no Name.
  inline std::vector<float>
  read_points(const std::string &file)
  {
    const std::string text  = file_text(file);
    const auto        start = text.find("<Points>");
    AssertThrow(start != std::string::npos,
                dealii::ExcMessage("no <Points> in " + file));
    return decode_array(text, text.find("<DataArray", start));
  }

  /// The piece files DIRECTORY/vtu/PREFIX*.vtu of a run, sorted (one
  /// rank: "solution_" gives every snapshot, "solution_0" the regular
  /// ones).
  inline std::vector<std::string>
  snapshot_files(const std::string &directory, const std::string &prefix)
  {
    std::vector<std::string> files;
    for (const auto &entry :
         std::filesystem::directory_iterator(directory + "/vtu"))
      {
        const std::string file = entry.path().filename().string();
        if (file.rfind(prefix, 0) == 0 && file.size() > 4 &&
            file.substr(file.size() - 4) == ".vtu")
          files.push_back(directory + "/vtu/" + file);
      }
    std::sort(files.begin(), files.end());
    return files;
  }
} // namespace fgimpact_tests

#endif
