// Comma-separated text as the authoring inputs write it (revolution profiles, stroke lists): the
// one splitter and number reader both use, so that a field means the same in every CSV we read.
// Lines end at '\n' (a '\r' before it is a blank), fields are split at ',' and trimmed of blanks
// (space, tab, '\r'), and '#' starts a comment: at the start of a line only, or anywhere, as the
// format says. Numbers are read with strtod over the whole field: "nan", "inf" and overflow (as
// infinity) are read, for the caller to refuse with their place; "1.2.3" or "" are not numbers.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bake {

enum class CsvComments { LineStart, Anywhere };

struct CsvLine {
  std::size_t number = 0;           // 1-based, as editors count
  std::vector<std::string> fields;  // none when the line is blank or only a comment
  bool comment = false;             // the line held a comment
};

// Every line of `text`, blank ones included (some formats give them a meaning).
std::vector<CsvLine> splitCsv(std::string_view text, CsvComments comments);

// Whether `field` is, whole, a number; the number in `out`.
bool parseCsvNumber(const std::string& field, double& out);

}  // namespace bake
