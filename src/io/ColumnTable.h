// Rows of one kind written as named columns, once for JSON and CSV: the LOD levels (LodIO) and the
// granularity rows (GranularityIO) keep one list of columns each, so a key in the JSON is the same
// column in the CSV.
#pragma once

#include <functional>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace conescope {

template <typename Row>
struct NamedColumn {
    const char* key;
    std::function<nlohmann::json(const Row&)> value;
};

// A CSV cell: text as it is, floating point with 17 digits (it reads back to the same double).
inline std::string csvCell(const nlohmann::json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number_float()) {
        std::ostringstream text;
        text << std::setprecision(17) << value.get<double>();
        return text.str();
    }
    return value.dump();
}

template <typename Row>
nlohmann::json rowToJson(const std::vector<NamedColumn<Row>>& columns, const Row& row) {
    nlohmann::json json = nlohmann::json::object();
    for (const NamedColumn<Row>& column : columns) json[column.key] = column.value(row);
    return json;
}

template <typename Row>
void writeCsvHeader(const std::vector<NamedColumn<Row>>& columns, std::ostream& out) {
    for (size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i].key;
    out << "\n";
}

template <typename Row>
void writeCsvRow(const std::vector<NamedColumn<Row>>& columns, const Row& row, std::ostream& out) {
    for (size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << csvCell(columns[i].value(row));
    out << "\n";
}

}  // namespace conescope
