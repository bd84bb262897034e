// Text made safe for a terminal (engine/core/printable_text.h): control bytes and broken UTF-8
// escaped, a library's log lines prefixed with their colour dropped.
#include <gtest/gtest.h>

#include "engine/core/printable_text.h"

namespace pyro {
namespace {

TEST(PrintableText, EscapesControlBytesAndBrokenUtf8) {
  EXPECT_EQ(printable("plain, caf\xc3\xa9"), "plain, caf\xc3\xa9");
  EXPECT_EQ(printable("a\x1b[31mb"), "a\\x1b[31mb");
  EXPECT_EQ(printable("x\xff\xc3"), "x\\xff\\xc3");
  EXPECT_EQ(printable("line\nbreak\x7f"), "line\\x0abreak\\x7f");
}

// OpenVDB's log4cplus layout colours each line; a file name in it may hold anything.
TEST(PrintableText, LogLinesArePrefixedWithoutColourAndEscaped) {
  const std::string log = "\x1b[33m WARN: duplicate grid name \"density\" in /tmp/a\x1b" "b.vdb\x1b[0m\n\n"
                          "second line\r\n";
  EXPECT_EQ(printable_lines(log, "pyro: OpenVDB: "),
            "pyro: OpenVDB:  WARN: duplicate grid name \"density\" in /tmp/a\\x1bb.vdb\n"
            "pyro: OpenVDB: second line\n");
  EXPECT_EQ(printable_lines("", "p: "), "");
}

}  // namespace
}  // namespace pyro
