#include "engine/io/json_document.h"

#include <string_view>
#include <utility>
#include <vector>

#include "engine/io/parameter_text.h"

namespace pyro {

using json = nlohmann::json;

// nlohmann reports the 1-based index of the last byte it read (one past the end for an
// unexpected end of input). Columns count characters (UTF-8 lead bytes), starting at 1.
std::string line_and_column(const std::string& text, std::size_t position) {
  const std::size_t index = position > 0 ? position - 1 : 0;
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < index && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

namespace {

class JsonDocumentBuilder final : public nlohmann::json_sax<json> {
 public:
  explicit JsonDocumentBuilder(const std::string& text) : text_(text) {}

  json& root() { return root_; }
  bool failed() const { return failed_; }
  const std::string& error_place() const { return error_place_; }
  const std::string& error_message() const { return error_message_; }

  bool null() override { return put(nullptr) != nullptr; }
  bool boolean(bool v) override { return put(v) != nullptr; }
  bool number_integer(number_integer_t v) override { return put(v) != nullptr; }
  bool number_unsigned(number_unsigned_t v) override { return put(v) != nullptr; }
  bool number_float(number_float_t v, const string_t&) override { return put(v) != nullptr; }
  bool string(string_t& v) override { return put(std::move(v)) != nullptr; }
  bool binary(binary_t& v) override { return put(json::binary(std::move(v))) != nullptr; }

  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    json& object = *stack_.back();
    if (object.contains(k)) {
      return fail(current_pointer() + "/" + escape_pointer_token(k),
                  "duplicate key " + in_quotes(k) + "; each key may appear only once in an object");
    }
    pending_ = &object[k];
    pending_token_ = "/" + escape_pointer_token(k);
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token,
                   const json::exception& ex) override {
    std::string message;
    if (ex.id == 406) {  // out_of_range.406: number overflow
      message =
          "expected a number within the range of a double (about 1.8e308), found " + last_token;
    } else {
      // "[json.exception.parse_error.101] parse error at line 1, column 9: syntax error ..."
      // -> keep what follows the position, which nlohmann sometimes gets wrong.
      message = ex.what();
      const std::size_t at = message.find("parse error");
      const std::size_t colon = message.find(": ", at == std::string::npos ? 0 : at);
      if (colon != std::string::npos) message = message.substr(colon + 2);
      message = "invalid JSON: " + message;
    }
    return fail(line_and_column(text_, position), message);
  }

 private:
  template <class T>
  json* put(T&& value) {
    if (stack_.empty()) {
      root_ = json(std::forward<T>(value));
      last_token_.clear();
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      last_token_ = "/" + std::to_string(top.size());
      top.push_back(json(std::forward<T>(value)));
      return &top.back();
    }
    *pending_ = json(std::forward<T>(value));
    last_token_ = pending_token_;
    return pending_;
  }

  bool open(json&& container) {
    if (stack_.size() >= kMaxDepth) {  // scenes nest 4 deep; this keeps recursion bounded
      return fail(current_pointer(), "expected at most " + std::to_string(kMaxDepth) +
                                         " levels of nested arrays and objects, found more");
    }
    json* v = put(std::move(container));
    stack_.push_back(v);
    tokens_.push_back(last_token_);
    return true;
  }

  bool close() {
    stack_.pop_back();
    tokens_.pop_back();
    return true;
  }

  std::string current_pointer() const {
    std::string p;
    for (const std::string& t : tokens_) p += t;
    return p;
  }

  bool fail(std::string place, std::string message) {
    failed_ = true;
    error_place_ = std::move(place);
    error_message_ = std::move(message);
    return false;
  }

  static constexpr std::size_t kMaxDepth = 64;

  const std::string& text_;
  json root_;
  std::vector<json*> stack_;         // open containers, outermost first
  std::vector<std::string> tokens_;  // "/key" or "/index" of each open container
  json* pending_ = nullptr;          // slot for the value after the last key
  std::string pending_token_, last_token_;
  bool failed_ = false;
  std::string error_place_, error_message_;
};

}  // namespace

JsonDocument parse_json_document(const std::string& text) {
  JsonDocumentBuilder builder(text);
  json::sax_parse(text, &builder, json::input_format_t::json, /*strict=*/true,
                  /*ignore_comments=*/false);
  JsonDocument document;
  document.failed = builder.failed();
  if (document.failed) {
    document.error_place = builder.error_place();
    document.error_message = builder.error_message();
  } else {
    document.root = std::move(builder.root());
  }
  return document;
}

}  // namespace pyro
