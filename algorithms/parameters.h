// The typed parameters of a reconstruction algorithm (survey, Table 1, column "Param
// count"): each has a name, a default and a valid range, and a value set by name is
// checked against them once, before the algorithm runs.
#pragma once

#include <map>
#include <span>
#include <string>
#include <string_view>

namespace curvebench::algorithms {

// What values a parameter takes: any real number in its range, or only whole ones.
enum class Parameter_type { real, integer };

// One parameter of an algorithm, as Algorithm::parameters lists it.
struct Parameter {
  std::string_view name;                        // the key of name=value: "beta"
  Parameter_type type = Parameter_type::real;   // integer: a value must be whole
  double default_value = 0;                     // the value when none is set
  // The smallest valid value; the largest is `maximum`.
  double minimum = 0, maximum = 0;  // closed range of valid values
  std::string_view meaning;          // one line, for `curvebench list`
};

// Values by name; a parameter not set takes its default.
class Parameter_values {
 public:
  Parameter_values() = default;
  // Values by name, e.g. {{"beta", 1.7}}; checked only by check().
  Parameter_values(std::initializer_list<std::pair<const std::string, double>> values) : values_(values) {}

  // Sets or replaces the value of `name`; checked only by check().
  void set(std::string name, double value) { values_[std::move(name)] = value; }
  // Whether a value is set for `name` (a default does not count).
  bool has(std::string_view name) const { return values_.find(name) != values_.end(); }
  // The value of `parameter`, or its default.
  double operator[](const Parameter& parameter) const;

  // Throws std::invalid_argument naming the culprit unless every value set names one of
  // `parameters`, lies in its range and, for an integer, is whole.
  void check(std::span<const Parameter> parameters, std::string_view algorithm) const;

  // "name=value,..." (sorted by name), as results and file names record them.
  std::string to_string() const;
  // Parses "name=value,name=value" (empty: no value); throws std::invalid_argument.
  static Parameter_values parse(std::string_view text);

  // The values set, by name (defaults not included).
  const std::map<std::string, double, std::less<>>& values() const { return values_; }

 private:
  std::map<std::string, double, std::less<>> values_;
};

}  // namespace curvebench::algorithms
