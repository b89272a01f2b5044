// The --report JSON record shared by every tool (spec: formats/report.md, schema:
// formats/report.schema.json). Bump kReportVersion on any incompatible change.
#pragma once

namespace bake::format::report {

inline constexpr const char* kSchemaId = "bake-report";
inline constexpr int kVersion = 1;

}  // namespace bake::format::report
