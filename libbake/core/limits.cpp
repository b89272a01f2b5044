#include "bake/core/limits.h"

#include <cerrno>
#include <cstdlib>

namespace bake {
namespace {

Budgets& current() {
  static Budgets values;
  return values;
}

constexpr Budget kAll[] = {Budget::InputBytes, Budget::Triangles, Budget::TextureSide, Budget::Grooves,
                           Budget::Primitives, Budget::FieldValues, Budget::ControlPoints, Budget::DecodedBytes,
                           Budget::Crossings, Budget::ProfileWork,
                           Budget::TamWork};

}  // namespace

std::uint64_t& Budgets::operator[](Budget which) {
  switch (which) {
    case Budget::InputBytes: return inputBytes;
    case Budget::Triangles: return triangles;
    case Budget::TextureSide: return textureSide;
    case Budget::Grooves: return grooves;
    case Budget::Primitives: return primitives;
    case Budget::FieldValues: return fieldValues;
    case Budget::ControlPoints: return controlPoints;
    case Budget::DecodedBytes: return decodedBytes;
    case Budget::Crossings: return crossings;
    case Budget::ProfileWork: return profileWork;
    case Budget::TamWork: return tamWork;
  }
  return inputBytes;
}

std::uint64_t Budgets::operator[](Budget which) const { return (*const_cast<Budgets*>(this))[which]; }

const char* budgetName(Budget which) {
  switch (which) {
    case Budget::InputBytes: return "input-bytes";
    case Budget::Triangles: return "triangles";
    case Budget::TextureSide: return "texture-side";
    case Budget::Grooves: return "grooves";
    case Budget::Primitives: return "primitives";
    case Budget::FieldValues: return "field-values";
    case Budget::ControlPoints: return "control-points";
    case Budget::DecodedBytes: return "decoded-bytes";
    case Budget::Crossings: return "crossings";
    case Budget::ProfileWork: return "profile-work";
    case Budget::TamWork: return "tam-work";
  }
  return "?";
}

bool budgetFromName(const std::string& name, Budget& which) {
  for (const Budget candidate : kAll) {
    if (name == budgetName(candidate)) {
      which = candidate;
      return true;
    }
  }
  return false;
}

std::string describeBudgets() {
  std::string text;
  for (const Budget which : kAll) {
    if (!text.empty()) text += ", ";
    text += std::string(budgetName(which)) + "=" + std::to_string(budgets()[which]);
  }
  return text;
}

const Budgets& budgets() { return current(); }
void setBudgets(const Budgets& values) { current() = values; }

Status applyBudgetSetting(const std::string& setting) {
  const std::size_t equals = setting.find('=');
  Budget which{};
  if (equals == std::string::npos || !budgetFromName(setting.substr(0, equals), which)) {
    return usageError("--budget " + setting + ": expected NAME=N with NAME one of: " + describeBudgets());
  }
  const std::string number = setting.substr(equals + 1);
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(number.c_str(), &end, 10);
  if (number.empty() || number[0] == '-' || *end != '\0' || errno == ERANGE || value == 0) {
    return usageError("--budget " + setting + ": '" + number + "' is not a positive integer");
  }
  current()[which] = value;
  return {};
}

Status checkBudget(Budget which, std::uint64_t amount, const std::string& what, Location where) {
  const std::uint64_t limit = budgets()[which];
  if (amount <= limit) return {};
  return invalidInput(std::to_string(amount) + " " + what + " exceed the budget of " + std::to_string(limit) +
                          " (raise it with --budget " + budgetName(which) + "=N)",
                      std::move(where));
}

}  // namespace bake
