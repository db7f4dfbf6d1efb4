// io: size-limited text files and strict JSON.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "wattswath/io/strict_json.hpp"
#include "wattswath/io/text_file.hpp"

namespace io = wattswath::io;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("wattswath_test_io_" + name);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string refusal(const std::string& path, const io::TextFileLimit& limit) {
  try {
    io::readTextFile(path, limit);
  } catch (const io::FileError& e) {
    return e.what();
  }
  return "";
}

std::string jsonRefusal(const std::string& text, int depth = 8) {
  try {
    io::parseStrictJson(text, depth);
  } catch (const io::JsonError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(TextFile, ReadsAFileAtTheLimitWholeAndByteForByte) {
  const std::string text = std::string("a\0b\r\n", 5) + std::string(1000, 'x');
  const auto p = write("at_limit", text);
  EXPECT_EQ(io::readTextFile(p, {static_cast<long long>(text.size()), "test files", ""}), text);
  fs::remove(p);
}

TEST(TextFile, RefusesAFileOneByteOverTheLimitNamingItsSizeTheLimitAndTheHint) {
  const auto p = write("over_limit", std::string(1025, 'x'));
  const std::string e = refusal(p, {1024, "test files", "split it"});
  EXPECT_EQ(e, p + ": the file has 1025 bytes; test files of at most 1024 bytes (0.000976562 MiB) are read (split it)");
  fs::remove(p);
}

TEST(TextFile, ReadsAPipeUpToTheLimitAndRefusesItBeyond) {
  // /dev/zero has no size: it is read up to the limit and then refused, not read forever.
  const std::string e = refusal("/dev/zero", {4096, "test files", ""});
  EXPECT_NE(e.find("/dev/zero: the file has "), std::string::npos) << e;
  EXPECT_NE(e.find("is a pipe"), std::string::npos) << e;
}

TEST(TextFile, AMissingFileIsNamed) {
  EXPECT_EQ(refusal("/nonexistent/wattswath.json", {1024, "test files", ""}),
            "/nonexistent/wattswath.json: cannot open the file");
}

TEST(StrictJson, ParsesValidJsonWithinTheDepth) {
  const auto j = io::parseStrictJson(R"({"a": [1, {"b": 2}], "c": {"a": 3}})", 3);
  EXPECT_EQ(j.at("a").at(1).at("b"), 2);
  EXPECT_EQ(j.at("c").at("a"), 3);  // the same key in another object is fine
}

TEST(StrictJson, RefusesAKeyGivenTwiceInOneObjectNamingIt) {
  EXPECT_EQ(jsonRefusal(R"({"mass_kg": 1.3, "x": {"y": 1}, "mass_kg": 13})"),
            "key \"mass_kg\" appears twice in one JSON object");
  EXPECT_EQ(jsonRefusal(R"([{"a": 1}, {"b": {"c": 1, "c": 2}}])"), "key \"c\" appears twice in one JSON object");
  try {
    io::parseStrictJson(R"({"c": 1, "c": 2})", 4);
    ADD_FAILURE() << "accepted a repeated key";
  } catch (const io::JsonError& e) {
    EXPECT_EQ(e.problem(), io::JsonProblem::duplicate_key);
    EXPECT_EQ(e.key(), "c");
  }
}

TEST(StrictJson, RefusesNestingBeyondTheDepthBeforeBuildingIt) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(jsonRefusal(deep, 64), "JSON nested more than 64 levels deep");
  EXPECT_EQ(jsonRefusal("[[1]]", 2), "");
  EXPECT_EQ(jsonRefusal("[[[1]]]", 2), "JSON nested more than 2 levels deep");
}

TEST(StrictJson, InvalidJsonAndOverflowingNumbersSayNotValidJson) {
  EXPECT_EQ(jsonRefusal("{\"a\": }").rfind("not valid JSON: ", 0), 0u);
  EXPECT_EQ(jsonRefusal("[1e999]").rfind("not valid JSON: ", 0), 0u);
}

TEST(StrictJson, OrderedParsingKeepsTheKeyOrderAndTheSameChecks) {
  const auto j = io::parseStrictOrderedJson(R"({"z": 1, "a": 2})", 4);
  EXPECT_EQ(j.begin().key(), "z");
  EXPECT_THROW(io::parseStrictOrderedJson(R"({"z": 1, "z": 2})", 4), io::JsonError);
}
