// record_dump: reads one measured record with the library's readers (bearing_records, and
// bearing_records_full when built) and shows what it read, for the Python test check_readers.py,
// which writes the files with other tools (scipy, h5py, wave, numpy, csv).
//
//   record_dump FILE [--channel NAME] [--rate HZ] [--unit UNIT] [--scale S] [--dataset PATH]
//               [--samples OUT]
//
// Prints the record's metadata as one JSON object on stdout and writes its samples [SI] to OUT
// as raw little-endian float64. An InputError prints its message on stderr and exits 2 (as
// bearing-sim does), anything else exits 1.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/errors.h"
#include "bearing/records/record_formats.h"
#ifdef BEARING_RECORDS_FULL
#include "bearing/records/full_record_formats.h"
#endif

namespace {

std::vector<bearing::RecordFormat> formats() {
  std::vector<bearing::RecordFormat> f = bearing::base_record_formats();
#ifdef BEARING_RECORDS_FULL
  f = bearing::with_formats(f, bearing::full_record_formats());
#endif
  return f;
}

void store_f8_le(char* out, double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  for (int i = 0; i < 8; ++i) out[i] = static_cast<char>((bits >> (8 * i)) & 0xffu);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: record_dump FILE [--channel NAME] [--rate HZ] [--unit UNIT] [--scale S] "
                 "[--dataset PATH] [--samples OUT]\n";
    return 2;
  }
  bearing::RecordOptions options;
  std::string samples_out;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--channel")
      options.channel = value;
    else if (flag == "--rate")
      options.rate = std::strtod(value.c_str(), nullptr);
    else if (flag == "--unit")
      options.unit = value;
    else if (flag == "--scale")
      options.scale = std::strtod(value.c_str(), nullptr);
    else if (flag == "--dataset")
      options.dataset = value;
    else if (flag == "--samples")
      samples_out = value;
    else {
      std::cerr << "record_dump: unknown option " << flag << "\n";
      return 2;
    }
  }
  try {
    const bearing::MeasuredRecord r = bearing::read_record(argv[1], options, formats());
    nlohmann::json j;
    j["file"] = r.file;
    j["channel"] = r.channel;
    j["samples"] = r.samples.size();
    j["quantity"] = bearing::name_of(bearing::kMeasuredQuantities, r.quantity);
    j["si_unit"] = std::string(bearing::si_unit_of(r.quantity));
    j["rate"] = r.rate;
    j["rate_source"] = bearing::name_of(bearing::kRecordSources, r.rate_source);
    j["rate_origin"] = r.rate_origin;
    j["unit"] = bearing::name_of(bearing::kRecordUnits, r.unit);
    j["unit_source"] = bearing::name_of(bearing::kRecordSources, r.unit_source);
    j["unit_origin"] = r.unit_origin;
    j["scale"] = r.scale;
    j["shaft_speed"] = r.shaft_speed ? nlohmann::json(*r.shaft_speed) : nlohmann::json();
    j["shaft_speed_origin"] = r.shaft_speed_origin;
    std::cout << j.dump() << "\n";
    if (!samples_out.empty()) {
      std::string bytes(8 * r.samples.size(), '\0');
      for (std::size_t i = 0; i < r.samples.size(); ++i) store_f8_le(&bytes[8 * i], r.samples[i]);
      std::ofstream(samples_out, std::ios::binary) << bytes;
    }
    return 0;
  } catch (const bearing::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "record_dump: internal error: " << e.what() << "\n";
    return 1;
  }
}
