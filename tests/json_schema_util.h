#pragma once
// A JSON Schema (draft 2020-12) validator for the keywords resources/scene.schema.json uses, so
// tests can hold the schema and the loader to the same files: type, enum, const, properties,
// additionalProperties, required, propertyNames, items, minItems, maxItems, minimum, maximum,
// exclusiveMinimum, exclusiveMaximum, minLength, allOf, anyOf, oneOf, not, if/then/else and local
// $ref (JSON pointers into the schema). An unknown keyword fails loudly, so the schema cannot use
// one that this would silently skip.
#include <nlohmann/json.hpp>

#include <set>
#include <stdexcept>
#include <string>

namespace testutil {

class JsonSchema {
public:
    explicit JsonSchema(nlohmann::json schema) : root_(std::move(schema)) {}

    /// The first violation as "PATH: problem", or "" when `value` is valid.
    [[nodiscard]] std::string validate(const nlohmann::json& value) const { return check(root_, value, "$"); }

private:
    using json = nlohmann::json;

    static bool hasType(const json& v, const std::string& t) {
        if (t == "object") return v.is_object();
        if (t == "array") return v.is_array();
        if (t == "string") return v.is_string();
        if (t == "number") return v.is_number();
        if (t == "integer")
            return v.is_number_integer() ||
                   (v.is_number_float() && v.get<double>() == double(int64_t(v.get<double>())));
        if (t == "boolean") return v.is_boolean();
        if (t == "null") return v.is_null();
        throw std::invalid_argument("schema: unknown type " + t);
    }

    const json& resolve(const std::string& ref) const {
        if (!ref.starts_with("#")) throw std::invalid_argument("schema: only local $ref: " + ref);
        return root_.at(json::json_pointer(ref.substr(1)));
    }

    std::string check(const json& s, const json& v, const std::string& path) const {
        static const std::set<std::string> kKnown = {"$schema",
                                                     "$id",
                                                     "title",
                                                     "description",
                                                     "$defs",
                                                     "$ref",
                                                     "type",
                                                     "enum",
                                                     "const",
                                                     "properties",
                                                     "additionalProperties",
                                                     "required",
                                                     "propertyNames",
                                                     "items",
                                                     "minItems",
                                                     "maxItems",
                                                     "minimum",
                                                     "maximum",
                                                     "exclusiveMinimum",
                                                     "exclusiveMaximum",
                                                     "minLength",
                                                     "allOf",
                                                     "anyOf",
                                                     "oneOf",
                                                     "not",
                                                     "if",
                                                     "then",
                                                     "else"};
        for (const auto& item : s.items())
            if (!kKnown.contains(item.key())) throw std::invalid_argument("schema: unsupported keyword " + item.key());
        if (s.contains("$ref"))
            if (std::string e = check(resolve(s["$ref"]), v, path); !e.empty()) return e;
        if (s.contains("type")) {
            const json& t = s["type"];
            bool ok = false;
            if (t.is_string()) ok = hasType(v, t);
            else
                for (const auto& one : t) ok = ok || hasType(v, one);
            if (!ok) return path + ": expected type " + t.dump() + ", got " + v.type_name();
        }
        if (s.contains("enum")) {
            bool found = false;
            for (const auto& e : s["enum"]) found = found || e == v;
            if (!found) return path + ": not one of " + s["enum"].dump();
        }
        if (s.contains("const") && s["const"] != v) return path + ": expected " + s["const"].dump();
        if (v.is_number()) {
            const double x = v.get<double>();
            if (s.contains("minimum") && !(x >= s["minimum"].get<double>())) return path + ": below minimum";
            if (s.contains("maximum") && !(x <= s["maximum"].get<double>())) return path + ": above maximum";
            if (s.contains("exclusiveMinimum") && !(x > s["exclusiveMinimum"].get<double>()))
                return path + ": not above exclusiveMinimum";
            if (s.contains("exclusiveMaximum") && !(x < s["exclusiveMaximum"].get<double>()))
                return path + ": not below exclusiveMaximum";
        }
        if (v.is_string() && s.contains("minLength") && v.get<std::string>().size() < s["minLength"].get<size_t>())
            return path + ": shorter than minLength";
        if (v.is_array()) {
            if (s.contains("minItems") && v.size() < s["minItems"].get<size_t>()) return path + ": too few items";
            if (s.contains("maxItems") && v.size() > s["maxItems"].get<size_t>()) return path + ": too many items";
            if (s.contains("items"))
                for (size_t i = 0; i < v.size(); ++i)
                    if (std::string e = check(s["items"], v[i], path + "[" + std::to_string(i) + "]"); !e.empty())
                        return e;
        }
        if (v.is_object()) {
            if (s.contains("required"))
                for (const auto& r : s["required"])
                    if (!v.contains(r.get<std::string>())) return path + ": missing " + r.get<std::string>();
            for (const auto& item : v.items()) {
                const std::string sub = path + "." + item.key();
                if (s.contains("propertyNames"))
                    if (std::string e = check(s["propertyNames"], json(item.key()), sub); !e.empty()) return e;
                if (s.contains("properties") && s["properties"].contains(item.key())) {
                    if (std::string e = check(s["properties"][item.key()], item.value(), sub); !e.empty()) return e;
                } else if (s.contains("additionalProperties")) {
                    const json& a = s["additionalProperties"];
                    if (a.is_boolean()) {
                        if (!a.get<bool>()) return sub + ": unknown key";
                    } else if (std::string e = check(a, item.value(), sub); !e.empty()) {
                        return e;
                    }
                }
            }
        }
        if (s.contains("allOf"))
            for (const auto& one : s["allOf"])
                if (std::string e = check(one, v, path); !e.empty()) return e;
        if (s.contains("anyOf")) {
            bool any = false;
            for (const auto& one : s["anyOf"]) any = any || check(one, v, path).empty();
            if (!any) return path + ": matches none of anyOf";
        }
        if (s.contains("oneOf")) {
            int matches = 0;
            for (const auto& one : s["oneOf"]) matches += check(one, v, path).empty();
            if (matches != 1) return path + ": matches " + std::to_string(matches) + " of oneOf (expected 1)";
        }
        if (s.contains("not") && check(s["not"], v, path).empty()) return path + ": matches a 'not' schema";
        if (s.contains("if")) {
            const bool holds = check(s["if"], v, path).empty();
            const char* branch = holds ? "then" : "else";
            if (s.contains(branch))
                if (std::string e = check(s[branch], v, path); !e.empty()) return e;
        }
        return "";
    }

    json root_;
};

} // namespace testutil
