#include "granular/model/configuration_file.hpp"

#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/model/chain_recipe.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

TEST(ConfigurationFile, ReadsTypesWithCommentsAndBlanks) {
  EXPECT_EQ(parse_configuration_text("# header\n1\n\n 2  # light\n1", "t"), (Configuration{1, 2, 1}));
  EXPECT_EQ(parse_configuration_text("1\r\n2\r\n", "t"), (Configuration{1, 2}));
}

TEST(ConfigurationFile, NamesTheLineOfABadValue) {
  try {
    parse_configuration_text("1\n2\n3\n", "chain.txt");
    FAIL() << "accepted type 3";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("chain.txt:3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_configuration_text("1\n", "t"), InvalidInput);                       // one bead
  EXPECT_THROW(parse_configuration_text("", "t"), InvalidInput);                          // empty
  EXPECT_THROW(parse_configuration_text(std::string("1\n\0\n2", 5), "t"), InvalidInput);  // binary
  EXPECT_THROW(parse_configuration_text("1 2\n1\n", "t"), InvalidInput);                  // two per line
}

TEST(ConfigurationFile, ReadsRadii) {
  EXPECT_EQ(parse_radii_text("4.76e-3\n2.38e-3 # small\n", "r"), (std::vector<double>{4.76e-3, 2.38e-3}));
  EXPECT_THROW(parse_radii_text("1e-3\n-1e-3\n", "r"), InvalidInput);
  EXPECT_THROW(parse_radii_text("1e-3\nnan\n", "r"), InvalidInput);
  EXPECT_THROW(parse_radii_text("1e-3\ninf\n", "r"), InvalidInput);
  EXPECT_THROW(parse_radii_text("1e-3\n1e-3x\n", "r"), InvalidInput);
  EXPECT_THROW(parse_radii_text("1e-3\n0\n", "r"), InvalidInput);
}

TEST(ConfigurationFile, ReadsDisplacements) {
  EXPECT_EQ(parse_displacements_text("1e-7\n-2.5e-8 # left\n\n0\n", "u"), (std::vector<double>{1e-7, -2.5e-8, 0}));
  EXPECT_THROW(parse_displacements_text("1e-7\nnan\n", "u"), InvalidInput);
  EXPECT_THROW(parse_displacements_text("1e-7\n3m\n", "u"), InvalidInput);
  EXPECT_THROW(parse_displacements_text("# nothing\n", "u"), InvalidInput);
  try {
    read_displacements_file("/nonexistent/seed.txt", "seed_profile");
    FAIL() << "read a missing file";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.parameter(), "seed_profile");
  }
}

TEST(ConfigurationFile, ExampleFilesLoad) {
  EXPECT_EQ(read_configuration_file(std::string(GRANULAR_DATA_DIR) + "/examples/diatomic-10.types").size(), 10u);
  EXPECT_EQ(read_radii_file(std::string(GRANULAR_DATA_DIR) + "/examples/single-impurity-11.radii").size(), 11u);
  EXPECT_THROW(read_radii_file("/nonexistent/file"), InvalidInput);
}

// A case names a types or radii file by its path and the hash of the values read from it: replay
// and resume of a case whose file was edited since are refused naming the file and its path (the
// path alone once read an edited file as the same chain); comments and spacing do not count.
TEST(ConfigurationFile, AnEditedFileIsRefusedWhereACaseNamesIt) {
  const auto write = [](const std::string& path, const std::string& text) { std::ofstream(path) << text; };
  for (const bool radii : {false, true}) {
    const std::string name = radii ? "radii_file" : "config_file";
    const std::string path = testing::scratch_path("bead-file-hash", radii ? "chain.radii" : "chain.types");
    write(path, radii ? "0.00476\n0.00238\n0.00476\n" : "1\n2\n1\n");
    ChainRecipe r;
    if (radii) r.source = GivenRadii{.radii = read_radii_file(path), .file = path};
    else r.source = GivenTypes{.types = read_configuration_file(path), .file = path};
    nlohmann::json fields;
    describe_fields(r, fields);
    ASSERT_TRUE(fields.contains(name + "_hash")) << fields.dump();
    write(path, std::string("# the same values\n") + (radii ? "0.00476\n 0.00238\n0.00476\n" : "1\n 2\n1\n"));
    EXPECT_NO_THROW(parse_recipe_fields(fields)) << name;
    write(path, radii ? "0.00476\n0.00476\n0.00476\n" : "1\n1\n1\n");
    try {
      parse_recipe_fields(fields);
      ADD_FAILURE() << name << ": an edited file was accepted";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), name);
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace granular
