#include "io/scene/JsonErrorPosition.h"

#include <nlohmann/json.hpp>

namespace eikon {
namespace {

// Accepts every event and keeps the position of the first error.
class ErrorPositionSax : public nlohmann::json_sax<nlohmann::json> {
public:
    std::optional<std::size_t> byte;

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) override {
        byte = position;
        return false;
    }
};

}  // namespace

std::optional<std::size_t> jsonErrorByte(const std::string& text) {
    ErrorPositionSax sax;
    nlohmann::json::sax_parse(text, &sax);
    return sax.byte;
}

}  // namespace eikon
