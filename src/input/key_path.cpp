#include "input/key_path.hpp"

#include <cctype>
#include <vector>

namespace railmodal::input {
namespace {

struct Segment {
  std::string key;
  std::vector<size_t> indices;  // [i] after the key
};

bool bare_key_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

std::vector<Segment> parse_path(const std::string& path) {
  std::vector<Segment> segments;
  size_t i = 0;
  const auto bad = [&](const std::string& why) {
    throw std::invalid_argument("cannot read the key path '" + path + "': " + why);
  };
  while (true) {
    Segment s;
    if (i < path.size() && path[i] == '"') {
      const size_t end = path.find('"', i + 1);
      if (end == std::string::npos) bad("unterminated quote");
      s.key = path.substr(i + 1, end - i - 1);
      i = end + 1;
    } else {
      while (i < path.size() && bare_key_char(path[i])) s.key += path[i++];
    }
    if (s.key.empty()) bad("empty key at position " + std::to_string(i + 1));
    while (i < path.size() && path[i] == '[') {
      const size_t end = path.find(']', i);
      const std::string digits = end == std::string::npos ? "" : path.substr(i + 1, end - i - 1);
      if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos)
        bad("expected [index] with a number from 0");
      s.indices.push_back(std::stoul(digits));
      i = end + 1;
    }
    segments.push_back(s);
    if (i == path.size()) break;
    if (path[i] != '.') bad(std::string("unexpected '") + path[i] + "' at position " + std::to_string(i + 1));
    ++i;
  }
  return segments;
}

std::string names_in(const toml::array& array) {
  std::string names;
  for (const auto& item : array)
    if (item.is_table() && item.as_table().count("name") && item.as_table().at("name").is_string())
      names += (names.empty() ? "'" : ", '") + item.as_table().at("name").as_string().str + "'";
  return names.empty() ? "none has a name" : "names: " + names;
}

}  // namespace

std::string set_at_path(toml::value& document, const std::string& path, const toml::value& value) {
  const std::vector<Segment> segments = parse_path(path);
  toml::value* node = &document;
  std::string where;  // the reader's name of *node
  for (size_t s = 0; s < segments.size(); ++s) {
    const Segment& seg = segments[s];
    const bool last = s + 1 == segments.size();
    if (node->is_table()) {
      auto& table = node->as_table();
      where += (where.empty() ? "" : ".") + seg.key;
      if (!table.count(seg.key)) {
        if (!last || !seg.indices.empty())
          throw std::invalid_argument("no key '" + where + "' in the file to change");
        table[seg.key] = value;  // a new key: the reader checks it belongs
        return where;
      }
      node = &table.at(seg.key);
    } else if (node->is_array()) {
      // An array of tables: pick the table whose name is the key.
      auto& array = node->as_array();
      size_t found = array.size();
      for (size_t k = 0; k < array.size(); ++k)
        if (array[k].is_table() && array[k].as_table().count("name") && array[k].as_table().at("name").is_string() &&
            array[k].as_table().at("name").as_string().str == seg.key) {
          if (found != array.size())
            throw std::invalid_argument("two tables of '" + where + "' are named '" + seg.key + "'; use [index]");
          found = k;
        }
      if (found == array.size())
        throw std::invalid_argument("no table of '" + where + "' is named '" + seg.key + "' (" + names_in(array) + ")");
      where += "[" + std::to_string(found) + "]";
      node = &array[found];
    } else {
      throw std::invalid_argument("'" + where + "' is a value, not a table: it has no key '" + seg.key + "'");
    }
    for (size_t index : seg.indices) {
      if (!node->is_array()) throw std::invalid_argument("'" + where + "' is not an array: [" + std::to_string(index) + "] does not apply");
      auto& array = node->as_array();
      if (index >= array.size())
        throw std::invalid_argument("'" + where + "' has " + std::to_string(array.size()) + " entries: [" +
                                    std::to_string(index) + "] is beyond them");
      where += "[" + std::to_string(index) + "]";
      node = &array[index];
    }
    if (last) {
      *node = value;
      return where;
    }
  }
  return where;
}

}  // namespace railmodal::input
