#include "bench/runner/algorithm_file.h"

#include <fstream>
#include <iterator>
#include <algorithm>
#include <cctype>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/runner/results_table.h"

namespace curvebench::bench {
namespace {

using nlohmann::json;

// Reads one object's keys, each checked for its type; `where` names it in messages. A key
// not among `keys` is an error first: a misspelt key must not read as a missing one.
class Reader {
 public:
  Reader(const json& object, std::string where, std::initializer_list<std::string_view> keys)
      : object_(object), where_(std::move(where)) {
    if (!object_.is_object()) fail("is not a JSON object");
    for (const auto& [key, value] : object_.items())
      if (std::ranges::find(keys, key) == keys.end()) fail("unknown key '" + key + "'");
  }

  [[noreturn]] void fail(const std::string& what) const { throw std::invalid_argument(where_ + ": " + what); }

  const json* find(const std::string& key) {
    const auto found = object_.find(key);
    return found == object_.end() || found->is_null() ? nullptr : &*found;
  }

  std::string text(const std::string& key, std::optional<std::string> otherwise = std::nullopt) {
    const json* value = find(key);
    if (!value) {
      if (!otherwise) fail("needs \"" + key + "\"");
      return *otherwise;
    }
    if (!value->is_string()) fail("\"" + key + "\" must be a string");
    return value->get<std::string>();
  }

  std::optional<double> number(const std::string& key) {
    const json* value = find(key);
    if (!value) return std::nullopt;
    if (!value->is_number()) fail("\"" + key + "\" must be a number");
    return value->get<double>();
  }

  const std::string& where() const { return where_; }
  void rename(std::string where) { where_ = std::move(where); }

 private:
  const json& object_;
  std::string where_;
};

External_parameter parameter(const json& object, const std::string& where) {
  Reader r(object, where, {"name", "type", "default", "min", "max", "meaning"});
  External_parameter p;
  p.name = r.text("name");
  const std::string type = r.text("type", "real");
  if (type != "real" && type != "integer") r.fail("\"type\" is real or integer, not '" + type + "'");
  p.integer = type == "integer";
  const auto default_value = r.number("default"), minimum = r.number("min"), maximum = r.number("max");
  if (!default_value || !minimum || !maximum) r.fail("a parameter needs \"default\", \"min\" and \"max\"");
  p.default_value = *default_value, p.minimum = *minimum, p.maximum = *maximum;
  p.meaning = r.text("meaning", "");
  return p;
}

External_declaration declaration(const json& object, const std::string& where) {
  // Known, so that its refusal says why rather than "unknown key": files written for
  // earlier versions may hold it.
  Reader r(object, where,
           {"name", "command", "title", "input_format", "index_base", "parameters", "timeout", "repeatable", "condition"});
  External_declaration d;
  d.name = r.text("name");
  r.rename(where + ": algorithm '" + d.name + "'");
  if (object.contains("repeatable"))
    r.fail("\"repeatable\" is no longer a key: every algorithm must give the same output for the same input "
           "(seed its random generator with a constant, break ties by point index), and runs, hunts and merged "
           "shards compare on that; remove the key");
  d.command = r.text("command");
  d.title = r.text("title", "");
  const std::string format = r.text("input_format", "xy");
  if (format != "xy" && format != "csv") r.fail("\"input_format\" is xy or csv, not '" + format + "'");
  d.input_format = format == "csv" ? External_declaration::Point_format::csv : External_declaration::Point_format::xy;
  const double base = r.number("index_base").value_or(0);
  if (base != 0 && base != 1) r.fail("\"index_base\" is 0 or 1");
  d.index_base = static_cast<int>(base);
  if (const json* parameters = r.find("parameters")) {
    if (!parameters->is_array()) r.fail("\"parameters\" must be a list");
    for (std::size_t k = 0; k < parameters->size(); ++k)
      d.parameters.push_back(parameter((*parameters)[k], r.where() + ": parameter " + std::to_string(k + 1)));
  }
  d.timeout_seconds = r.number("timeout");
  if (const json* condition = r.find("condition")) {
    Reader c(*condition, r.where() + ": condition", {"statement", "epsilon_below", "rho_below", "uniformity_below"});
    d.epsilon_below = c.number("epsilon_below");
    d.rho_below = c.number("rho_below");
    d.uniformity_below = c.number("uniformity_below");
    d.condition = c.text("statement", d.epsilon_below ? "epsilon < " + format_number(*d.epsilon_below) : "none declared");
  }
  return d;
}

}  // namespace

std::vector<External_declaration> parse_algorithm_file(std::string_view text, std::string_view file) {
  const std::string name(file);
  const json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) throw std::invalid_argument(name + ": not JSON");
  Reader top(document, name, {"algorithms"});
  const json* list = top.find("algorithms");
  if (!list || !list->is_array()) top.fail("needs \"algorithms\", a list");
  std::vector<External_declaration> declarations;
  for (std::size_t k = 0; k < list->size(); ++k)
    declarations.push_back(declaration((*list)[k], name + ": algorithm " + std::to_string(k + 1)));
  return declarations;
}

std::vector<const algorithms::Algorithm*> load_algorithm_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(file.string() + ": cannot read the file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::vector<const algorithms::Algorithm*> declared;
  for (External_declaration& d : parse_algorithm_file(text, file.string())) {
    const std::string name = d.name;
    d.file = std::filesystem::absolute(file);
    // {dir}: the file's directory, so that a file and its programs move together.
    const std::string dir = d.file.parent_path().string();
    const bool plain = std::ranges::all_of(dir, [](char c) { return std::isalnum(c) || std::strchr("/._-+", c); });
    for (std::size_t at; (at = d.command.find("{dir}")) != std::string::npos;)
      d.command.replace(at, 5, plain ? dir : shell_quoted(dir));
    try {
      declared.push_back(&declare_external_algorithm(std::move(d)));
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(file.string() + ": algorithm '" + name + "': " + error.what());
    }
  }
  return declared;
}

}  // namespace curvebench::bench
