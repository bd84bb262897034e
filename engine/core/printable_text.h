#pragma once
// Text from files, arguments and third-party libraries made safe to print on a terminal.
#include <string>
#include <string_view>

namespace pyro {

// `text` with every byte a terminal would act on escaped: control characters (escape sequences
// included) as \xNN, and bytes that are not valid UTF-8 the same way. Text taken from files and
// arguments goes through it before it is printed.
std::string printable(std::string_view text);

// The lines of `text` (a library's log) each as `prefix` + the line printable, ANSI colour and
// style sequences (ESC [ ... m) dropped, empty lines left out; each ends with a newline.
std::string printable_lines(std::string_view text, const std::string& prefix);

}  // namespace pyro
