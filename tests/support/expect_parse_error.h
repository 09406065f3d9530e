// A test helper for the readers' error contract: a ParseError whose what() is one line,
// "FILE:LINE: message", for the expected file and line, with a message that mentions
// the expected text (usually the offending token, quoted).
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "geometry/io/parse_error.h"

namespace curvebench::testing {

// A malformed input for table-driven tests, and where and how it must be reported.
struct BadInput {
  const char* file_name;
  const char* text;
  std::size_t line;     // the line the error must name
  const char* mention;  // what the message must quote
};

template <class Parse>
void expect_parse_error(Parse&& parse, const std::string& file, std::size_t line,
                        std::string_view mention) {
  try {
    parse();
    ADD_FAILURE() << "no ParseError";
  } catch (const geometry::ParseError& error) {
    const std::string what = error.what();
    const std::string prefix = file + ":" + std::to_string(line) + ": ";
    EXPECT_TRUE(what.starts_with(prefix)) << what << "\ndoes not start with " << prefix;
    EXPECT_NE(what.find(mention, prefix.size()), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "not one line: " << what;
    EXPECT_EQ(error.file(), file);
    EXPECT_EQ(error.line(), line);
  }
}

}  // namespace curvebench::testing
