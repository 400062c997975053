#include "json_output.hpp"

#include <ostream>

#include "tetcut/io.hpp"

namespace tetcut::cli {

std::string json_text(const Json& value) {
  return value.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

bool write_json_file(const std::string& path, const Json& value, std::ostream& err) {
  const WriteResult w = write_file_atomically(path, json_text(value));
  if (!w.ok) err << "tetcut: " << w.error << "\n";
  return w.ok;
}

}  // namespace tetcut::cli
