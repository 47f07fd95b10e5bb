#include "geometry/io/json_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace geometry::io {

namespace {

using json = nlohmann::json;

struct Reader {
    const std::string& path;
    const std::string& label;
    std::size_t maxBytes;
    int maxDepth;

    [[nodiscard]] std::runtime_error error(const std::string& problem) const {
        return std::runtime_error(label + ": " + problem);
    }

    /// The whole file, refusing anything over maxBytes without reading more than that (so a
    /// FIFO or /dev/zero cannot exhaust memory).
    [[nodiscard]] std::string read() const {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::file_status status = fs::status(path, ec);
        if (!fs::exists(status)) throw error("no such file");
        if (fs::is_directory(status)) throw error("is a directory");
        const std::string limit = std::to_string(maxBytes >> 20) + " MiB";
        if (fs::is_regular_file(status)) {
            const auto size = fs::file_size(path, ec);
            if (!ec && size > maxBytes) throw error("larger than " + limit + " (" + std::to_string(size) + " bytes)");
        }
        std::ifstream in(path, std::ios::binary);
        if (!in) throw error(std::string("cannot be opened (") + std::strerror(errno) + ")");
        std::string text(maxBytes + 1, '\0');
        in.read(text.data(), std::streamsize(text.size()));
        if (in.bad()) throw error("cannot be read");
        text.resize(size_t(in.gcount()));
        if (text.size() > maxBytes) throw error("larger than " + limit);
        return text;
    }

    /// Refuses deep nesting while parsing, so a hostile file never builds a deep tree.
    [[nodiscard]] json parse(const std::string& text) const {
        const json::parser_callback_t limitDepth = [this](int depth, json::parse_event_t event, json&) {
            const bool opens = event == json::parse_event_t::object_start || event == json::parse_event_t::array_start;
            if (opens && depth + 1 > maxDepth)
                throw error("nested deeper than " + std::to_string(maxDepth) + " levels");
            return true;
        };
        try {
            return json::parse(text, limitDepth);
        } catch (const json::parse_error& e) {
            throw error("not valid JSON (" + lineAndColumn(text, e.byte) + ")");
        } catch (const json::exception& e) {
            // e.g. out_of_range for 1e999 (JSON has no infinity): nlohmann's reason, minus its tag
            const std::string what = e.what();
            const auto tag = what.find("] ");
            throw error("not valid JSON (" + (tag == std::string::npos ? what : what.substr(tag + 2)) + ")");
        }
    }

    /// 1-based line and column of a 1-based byte position, as in nlohmann's parse_error::byte.
    static std::string lineAndColumn(const std::string& text, std::size_t byte) {
        const std::size_t before = std::min(byte > 0 ? byte - 1 : 0, text.size());
        std::size_t line = 1, lineStart = 0;
        for (std::size_t i = 0; i < before; ++i)
            if (text[i] == '\n') ++line, lineStart = i + 1;
        return "line " + std::to_string(line) + ", column " + std::to_string(before - lineStart + 1);
    }
};

} // namespace

json readJsonFile(const std::string& path, const std::string& label, std::size_t maxBytes, int maxDepth) {
    const Reader reader{path, label, maxBytes, maxDepth};
    const std::string text = reader.read();
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw reader.error("file is empty");
    return reader.parse(text);
}

std::string describeJsonValue(const nlohmann::json& v) {
    if (v.is_object() || v.is_array() || v.is_null()) return v.type_name();
    std::string text = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(v.type_name()) + " " + text;
}

} // namespace geometry::io
