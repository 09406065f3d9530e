#include "algorithms/parameters.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace curvebench::algorithms {

double Parameter_values::operator[](const Parameter& parameter) const {
  const auto found = values_.find(parameter.name);
  return found == values_.end() ? parameter.default_value : found->second;
}

void Parameter_values::check(std::span<const Parameter> parameters, std::string_view algorithm) const {
  for (const auto& [name, value] : values_) {
    const auto parameter = std::ranges::find(parameters, std::string_view(name), &Parameter::name);
    if (parameter == parameters.end())
      throw std::invalid_argument(std::string(algorithm) + " has no parameter '" + name + "'");
    std::ostringstream range;
    range << '[' << parameter->minimum << ", " << parameter->maximum << ']';
    if (!(value >= parameter->minimum && value <= parameter->maximum))
      throw std::invalid_argument(std::string(algorithm) + ": " + name + " must lie in " + range.str());
    if (parameter->type == Parameter_type::integer && value != std::floor(value))
      throw std::invalid_argument(std::string(algorithm) + ": " + name + " must be a whole number");
  }
}

std::string Parameter_values::to_string() const {
  std::ostringstream text;
  text.precision(17);
  for (const auto& [name, value] : values_) text << (text.tellp() > 0 ? "," : "") << name << '=' << value;
  return text.str();
}

Parameter_values Parameter_values::parse(std::string_view text) {
  Parameter_values values;
  while (!text.empty()) {
    const std::string_view item = text.substr(0, text.find(','));
    text.remove_prefix(std::min(text.size(), item.size() + 1));
    const auto equals = item.find('=');
    if (equals == std::string_view::npos || equals == 0)
      throw std::invalid_argument("parameter '" + std::string(item) + "' is not name=value");
    const std::string_view number = item.substr(equals + 1);
    double value = 0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error != std::errc() || end != number.data() + number.size() || !std::isfinite(value))
      throw std::invalid_argument("parameter '" + std::string(item) + "' has no finite number after '='");
    values.set(std::string(item.substr(0, equals)), value);
  }
  return values;
}

}  // namespace curvebench::algorithms
