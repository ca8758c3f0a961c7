// JSON written as it is made, laid out exactly as nlohmann::json::dump(2) lays out the same
// document. A statistics file holds a row of a dozen numbers per cluster: building it as a tree of
// nlohmann objects (a map node and often a key string per number) cost more than writing the text.
// Members of an object must come in ascending key order, the order nlohmann's std::map keeps, and
// keys must be plain snake_case: either mistake throws std::logic_error, so the text cannot
// silently differ from the tree's.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace conescope {

class JsonWriter {
public:
    // Appends to `out`, which must outlive the writer.
    explicit JsonWriter(std::string& out);

    void beginObject();
    void endObject();
    void beginArray();
    void endArray();
    // The next member of the open object; `name` must outlive the object.
    void key(std::string_view name);
    // A number, bool, string or null, or a whole tree laid out at this depth; numbers and strings
    // are written by nlohmann's own serializer, so they read as dump() writes them.
    void value(const nlohmann::json& any);
    void value(double number) { value(nlohmann::json(number)); }
    void value(size_t count) { value(nlohmann::json(count)); }
    void value(bool flag) { value(nlohmann::json(flag)); }

private:
    struct Level {
        bool object;
        bool empty = true;
        bool keyed = false;  // an object's key is written and waits for its value
        std::string_view lastKey;
    };
    void beforeValue();
    void newItem();
    void end(char close);

    std::string& out_;
    nlohmann::detail::serializer<nlohmann::json> serializer_;
    std::vector<Level> levels_;
};

// `document`.dump(2) and a newline into the file at `path`; throws std::runtime_error naming the
// path when it cannot be written.
void writeJsonFile(const nlohmann::json& document, const std::string& path);

}  // namespace conescope
