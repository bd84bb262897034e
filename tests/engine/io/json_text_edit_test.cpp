// Text-level JSON edits: the value's bytes found by the scanner, replaced or added, and every
// other byte kept.
#include "engine/io/json_text_edit.h"

#include <gtest/gtest.h>

#include <string>

namespace pyro {
namespace {

using nlohmann::json;

// Brackets, quotes and escapes inside strings, numbers spelled unusually, keys with "/" and "~".
const std::string kEditSample = R"({
  "name": "a \"quoted\" [bracket} name\\",
  "a/b": {"x~y": 0.50},
  "list": [ 1.0e0 , [2, {"k": "]"}], 3 ],
  "nested": {
    "first": 0.250,
    "second": true
  },
  "flat": {"only": 1},
  "empty": {}
}
)";

std::string edit_span_text(const std::string& text, const std::string& pointer) {
  const auto span = find_json_value(text, pointer);
  if (!span) return "<none>";
  return text.substr(span->begin, span->end - span->begin);
}

TEST(JsonTextEdit, FindsTheBytesOfEachValue) {
  EXPECT_EQ(edit_span_text(kEditSample, "/name"), R"("a \"quoted\" [bracket} name\\")");
  EXPECT_EQ(edit_span_text(kEditSample, "/a~1b/x~0y"), "0.50");
  EXPECT_EQ(edit_span_text(kEditSample, "/list/0"), "1.0e0");
  EXPECT_EQ(edit_span_text(kEditSample, "/list/1"), R"([2, {"k": "]"}])");
  EXPECT_EQ(edit_span_text(kEditSample, "/list/1/1/k"), R"("]")");
  EXPECT_EQ(edit_span_text(kEditSample, "/list/2"), "3");
  EXPECT_EQ(edit_span_text(kEditSample, "/nested/first"), "0.250");
  EXPECT_EQ(edit_span_text(kEditSample, "/empty"), "{}");
  EXPECT_EQ(edit_span_text(kEditSample, "/list/3"), "<none>");
  EXPECT_EQ(edit_span_text(kEditSample, "/list/01"), "<none>");
  EXPECT_EQ(edit_span_text(kEditSample, "/nested/third"), "<none>");
  EXPECT_EQ(edit_span_text(kEditSample, "name"), "<none>");
  // Every span parses to the value nlohmann finds at the same pointer.
  const json tree = json::parse(kEditSample);
  for (const char* p : {"/name", "/a~1b", "/list", "/list/1/1", "/nested", "/flat/only", ""}) {
    EXPECT_EQ(json::parse(edit_span_text(kEditSample, p)), tree[json::json_pointer(p)]) << p;
  }
}

TEST(JsonTextEdit, PointerTokensFollowRfc6901) {
  EXPECT_EQ(split_json_pointer(""), std::vector<std::string>{});
  EXPECT_EQ(split_json_pointer("/a~1b/~0/"), (std::vector<std::string>{"a/b", "~", ""}));
  EXPECT_FALSE(split_json_pointer("a"));
  EXPECT_FALSE(split_json_pointer("/a~2"));
  EXPECT_FALSE(split_json_pointer("/a~"));
}

TEST(JsonTextEdit, ReplacingAValueKeepsEveryOtherByte) {
  const JsonTextEdit edit = set_json_value(kEditSample, "/nested/first", 0.75);
  ASSERT_FALSE(edit.failed()) << edit.error;
  const std::size_t at = kEditSample.find("0.250");
  EXPECT_EQ(edit.text, kEditSample.substr(0, at) + "0.75" + kEditSample.substr(at + 5));

  const JsonTextEdit inner = set_json_value(kEditSample, "/list/1/1/k", "new }");
  ASSERT_FALSE(inner.failed()) << inner.error;
  const std::size_t k = kEditSample.find(R"("]")");
  EXPECT_EQ(inner.text, kEditSample.substr(0, k) + R"("new }")" + kEditSample.substr(k + 3));
}

TEST(JsonTextEdit, AnEqualValueKeepsItsSpelling) {
  const JsonTextEdit edit = set_json_value(kEditSample, "/a~1b/x~0y", 0.5);
  ASSERT_FALSE(edit.failed()) << edit.error;
  EXPECT_EQ(edit.text, kEditSample);
}

TEST(JsonTextEdit, AMissingKeyIsAddedLastWithItsSiblingsIndent) {
  const JsonTextEdit lines = set_json_value(kEditSample, "/nested/third", json::array({1, 2, 3}));
  ASSERT_FALSE(lines.failed()) << lines.error;
  const std::string after_second = "\"second\": true";
  const std::size_t at = kEditSample.find(after_second) + after_second.size();
  EXPECT_EQ(lines.text, kEditSample.substr(0, at) + ",\n    \"third\": [1, 2, 3]" +
                            kEditSample.substr(at));

  const JsonTextEdit flat = set_json_value(kEditSample, "/flat/two", 2);
  ASSERT_FALSE(flat.failed()) << flat.error;
  EXPECT_NE(flat.text.find(R"("flat": {"only": 1, "two": 2})"), std::string::npos) << flat.text;

  const JsonTextEdit empty = set_json_value(kEditSample, "/empty/a~1b", "x");
  ASSERT_FALSE(empty.failed()) << empty.error;
  EXPECT_NE(empty.text.find(R"("empty": {"a/b": "x"})"), std::string::npos) << empty.text;

  const json expected = [] {
    json t = json::parse(kEditSample);
    t["nested"]["third"] = {1, 2, 3};
    return t;
  }();
  EXPECT_EQ(json::parse(lines.text), expected);
}

TEST(JsonTextEdit, RefusesWhatItCannotPlace) {
  const auto error_of = [](const std::string& pointer) {
    return set_json_value(kEditSample, pointer, 1).error;
  };
  EXPECT_NE(error_of("/list/3").find("expected an index of the array at \"/list\" (0 to 2)"),
            std::string::npos) << error_of("/list/3");
  EXPECT_NE(error_of("/list/-").find("found \"-\""), std::string::npos);
  EXPECT_NE(error_of("/missing/key").find("expected a value at \"/missing\""), std::string::npos);
  EXPECT_NE(error_of("/nested/first/x").find("expected an object or an array at \"/nested/first\""
                                             ", found a number"),
            std::string::npos) << error_of("/nested/first/x");
  EXPECT_NE(error_of("nested").find("expected a JSON pointer"), std::string::npos);
  EXPECT_TRUE(set_json_value(kEditSample, "/nested/first", NAN).failed());
  EXPECT_TRUE(set_json_value("{\"a\": [1,", "/a/0", 2).failed());
}

TEST(JsonTextEdit, WritesValuesCompactly) {
  EXPECT_EQ(compact_json_text(json::array({1, 2, 3})), "[1, 2, 3]");
  EXPECT_EQ(compact_json_text(json(0.1f)), "0.1");  // not 0.100000001490116
  EXPECT_EQ(compact_json_text(json(0.1)), "0.1");
  EXPECT_EQ(compact_json_text(json::parse(R"({"b": [0.5, "s"], "a": {}})")),
            R"({"a": {}, "b": [0.5, "s"]})");
  EXPECT_EQ(compact_json_text(json("a\"b")), R"("a\"b")");
  // The shortest float text reads back as the same float.
  for (const float f : {0.3f, 1e-7f, 12345.678f, 3.4e38f}) {
    EXPECT_EQ(json::parse(compact_json_text(json(f))).get<float>(), f);
  }
}

}  // namespace
}  // namespace pyro
