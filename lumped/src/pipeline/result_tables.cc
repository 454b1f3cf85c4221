// The tables of a result folder: the buffered file's failure, columns.json, a text file.

#include "result_tables.h"

#include <cerrno>

#include <nlohmann/json.hpp>

namespace bearing {

void BufferedFile::fail() const {
  throw OutputError("cannot write " + path_.string() + " (" + std::strerror(errno) + ")");
}

std::string columns_json(const std::vector<std::string>& files,
                         const std::vector<TableLayout>& tables) {
  nlohmann::json j;
  j["format"] =
      "NumPy .npy version 1.0: little-endian float64 ('<f8'), C order, shape [rows, columns]";
  j["usage"] =
      "columns = json.load(open('columns.json'))['tables']['response.npy']['columns']; "
      "a = numpy.load('response.npy'); ay = a[:, columns.index('ay')]";
  j["tables"] = nlohmann::json::object();
  for (std::size_t i = 0; i < tables.size(); ++i)
    j["tables"][files[i]] = {{"shape", {tables[i].rows, tables[i].columns.size()}},
                             {"columns", tables[i].columns},
                             {"units", tables[i].units}};
  return j.dump(2) + "\n";
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  BufferedFile f(path);
  f.text(text);
  f.close();
}

}  // namespace bearing
