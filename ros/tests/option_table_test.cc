// The node's parameter names are corridor_depth's flag names: every option of the table is a flag
// of tools/tool_flags.cc with the same type and default, and setting the flag sets the same field
// that the table names.

#include <cstdio>
#include <set>

#include <gflags/gflags.h>
#include <gtest/gtest.h>

#include "pipeline/option_table.h"
#include "tools/tool_flags.h"

namespace corridor {
namespace {

// Collects the options: name, type, the field's text.
class Collect : public OptionVisitor {
 public:
  struct Entry {
    std::string name, type, value;
  };
  void String(const char* n, std::string* f) override { entries.push_back({n, "string", *f}); }
  void Double(const char* n, double* f) override {
    char text[32];
    std::snprintf(text, sizeof(text), "%.17g", *f);
    entries.push_back({n, "double", text});
  }
  void Int(const char* n, int* f) override { entries.push_back({n, "int32", std::to_string(*f)}); }
  void Bool(const char* n, bool* f) override { entries.push_back({n, "bool", *f ? "true" : "false"}); }
  std::vector<Entry> entries;
};

std::vector<Collect::Entry> Entries(RecoverDepthOptions options) {
  Collect collect;
  VisitRecoverDepthOptions(&options, &collect);
  return collect.entries;
}

TEST(OptionTableTest, SameNamesTypesAndDefaultsAsTheToolFlags) {
  const auto entries = Entries(RecoverDepthOptions());
  EXPECT_GE(entries.size(), 20u);
  std::set<std::string> names;
  for (const auto& e : entries) {
    EXPECT_TRUE(names.insert(e.name).second) << e.name << " twice";
    gflags::CommandLineFlagInfo info;
    ASSERT_TRUE(gflags::GetCommandLineFlagInfo(e.name.c_str(), &info)) << e.name;
    EXPECT_EQ(info.type, e.type) << e.name;
    if (e.type == "double") {
      EXPECT_DOUBLE_EQ(std::stod(info.default_value), std::stod(e.value)) << e.name;
    } else {
      EXPECT_EQ(info.default_value, e.value) << e.name;
    }
  }
}

TEST(OptionTableTest, EachFlagSetsTheFieldTheTableNames) {
  for (const auto& e : Entries(RecoverDepthOptions())) {
    std::string value;
    if (e.type == "string") value = e.name == "solver" ? "grid" : "paper";
    if (e.type == "double") value = std::to_string(std::stod(e.value) * 0.5 + 0.125);
    if (e.type == "int32") value = std::to_string(std::stoi(e.value) + 3);
    if (e.type == "bool") value = e.value == "true" ? "false" : "true";
    gflags::FlagSaver saver;
    ASSERT_FALSE(gflags::SetCommandLineOption(e.name.c_str(), value.c_str()).empty()) << e.name;
    RecoverDepthOptions options;
    (void)RecoverDepthOptionsFromFlags(&options);  // Fills the options before checking them.
    // Exactly the named field took the new value, every other kept its default.
    const auto defaults = Entries(RecoverDepthOptions());
    const auto now = Entries(options);
    ASSERT_EQ(now.size(), defaults.size());
    for (size_t i = 0; i < now.size(); ++i) {
      if (now[i].name == e.name) {
        if (e.type == "double") {
          EXPECT_DOUBLE_EQ(std::stod(now[i].value), std::stod(value)) << e.name;
        } else {
          EXPECT_EQ(now[i].value, value) << e.name;
        }
      } else {
        EXPECT_EQ(now[i].value, defaults[i].value) << "setting --" << e.name << " changed "
                                                   << now[i].name;
      }
    }
  }
}

}  // namespace
}  // namespace corridor
