// Budgets (core/limits.h): settings, names, the check and its message, and the early checks in the
// readers that must refuse an input before allocating for it.
#include "bake/core/limits.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "bake/core/atomic_file.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

// Restores the default budgets after each test: they are process-wide.
class BudgetTest : public ::testing::Test {
 protected:
  void TearDown() override { setBudgets(Budgets{}); }
};

TEST_F(BudgetTest, SettingsByNameChangeOneBudget) {
  ASSERT_TRUE(applyBudgetSetting("triangles=1234").isOk());
  EXPECT_EQ(budgets().triangles, 1234u);
  EXPECT_EQ(budgets().grooves, Budgets{}.grooves);
  ASSERT_TRUE(applyBudgetSetting("input-bytes=18446744073709551615").isOk());
  EXPECT_EQ(budgets().inputBytes, 18446744073709551615ull);
}

TEST_F(BudgetTest, BadSettingsAreUsageErrors) {
  for (const char* bad : {"triangles", "triangles=", "triangles=-1", "triangles=0", "triangles=1e6", "triangles=12x",
                          "triangles=99999999999999999999", "nothing=3", "=3"}) {
    const Status status = applyBudgetSetting(bad);
    EXPECT_EQ(status.code(), ExitCode::Usage) << bad;
  }
  EXPECT_EQ(budgets().triangles, Budgets{}.triangles) << "a refused setting changes nothing";
}

TEST_F(BudgetTest, EveryBudgetHasAUniqueNameThatRoundTrips) {
  for (const Budget which : {Budget::InputBytes, Budget::Triangles, Budget::TextureSide, Budget::Grooves,
                             Budget::FieldValues}) {
    Budget back{};
    ASSERT_TRUE(budgetFromName(budgetName(which), back));
    EXPECT_EQ(back, which);
    EXPECT_NE(describeBudgets().find(budgetName(which)), std::string::npos);
  }
}

TEST_F(BudgetTest, CheckAllowsTheBudgetItselfAndNamesTheWayToRaiseIt) {
  ASSERT_TRUE(applyBudgetSetting("grooves=100").isOk());
  EXPECT_TRUE(checkBudget(Budget::Grooves, 100, "grooves", {"scene.json", ""}).isOk());
  const Status over = checkBudget(Budget::Grooves, 101, "grooves", {"scene.json", "/generators/0"});
  EXPECT_EQ(over.code(), ExitCode::InvalidInput);
  EXPECT_EQ(over.where().file, "scene.json");
  EXPECT_EQ(over.where().element, "/generators/0");
  EXPECT_NE(over.message().find("101 grooves exceed the budget of 100"), std::string::npos) << over.message();
  EXPECT_NE(over.message().find("--budget grooves=N"), std::string::npos) << over.message();
}

TEST_F(BudgetTest, FilesBeyondTheInputBudgetAreRefusedBeforeReading) {
  const fs::path file = test::freshTempDir("budget_input") / "data.bin";
  std::ofstream(file, std::ios::binary) << std::string(2000, 'x');
  ASSERT_TRUE(readFileBytes(file).isOk());
  ASSERT_TRUE(applyBudgetSetting("input-bytes=1999").isOk());
  const auto refused = readFileBytes(file);
  ASSERT_FALSE(refused.isOk());
  EXPECT_EQ(refused.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(refused.status().message().find("2000 bytes exceed"), std::string::npos);
}

}  // namespace
}  // namespace bake
