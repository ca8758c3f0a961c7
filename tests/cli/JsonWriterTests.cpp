// JsonWriter: the text it writes is what nlohmann::json::dump(2) writes for the same document, and
// the mistakes that would make it differ (keys out of order, a value without its key) throw.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "io/JsonWriter.h"

namespace conescope {
namespace {

TEST(JsonWriter, LaysOutADocumentAsNlohmannDumpDoes) {
    std::string text;
    JsonWriter json(text);
    json.beginObject();
    json.key("a_count");
    json.value(size_t(42));
    json.key("empty_array");
    json.beginArray();
    json.endArray();
    json.key("empty_object");
    json.beginObject();
    json.endObject();
    json.key("flag");
    json.value(false);
    json.key("numbers");
    json.beginArray();
    for (double x : {1.0, -0.0, 0.1, 1e-7, 1e300, 2.5e-308, 123456789.125, std::nan(""),
                     std::numeric_limits<double>::infinity()})
        json.value(x);
    json.endArray();
    json.key("rows");
    json.beginArray();
    for (size_t i = 0; i < 2; ++i) {
        json.beginObject();
        json.key("index");
        json.value(i);
        json.key("nested");
        json.value(nlohmann::json::array({nlohmann::json::array({1, 2}), nlohmann::json::object({{"z", nullptr}, {"b", "x"}})}));
        json.endObject();
    }
    json.endArray();
    json.key("text");
    json.value(nlohmann::json("quote \" backslash \\ tab \t bell \x07 \xc3\xa9t\xc3\xa9"));
    json.key("z_null");
    json.value(nlohmann::json(nullptr));
    json.endObject();

    nlohmann::json expected = {{"z_null", nullptr}, {"a_count", 42}, {"empty_array", nlohmann::json::array()},
                               {"empty_object", nlohmann::json::object()}, {"flag", false},
                               {"text", "quote \" backslash \\ tab \t bell \x07 \xc3\xa9t\xc3\xa9"}};
    expected["numbers"] = {1.0, -0.0, 0.1, 1e-7, 1e300, 2.5e-308, 123456789.125, std::nan(""),
                           std::numeric_limits<double>::infinity()};
    for (size_t i = 0; i < 2; ++i)
        expected["rows"].push_back({{"index", i}, {"nested", {{1, 2}, {{"z", nullptr}, {"b", "x"}}}}});
    EXPECT_EQ(text, expected.dump(2));
}

TEST(JsonWriter, ScalarsAndArraysAtTheTop) {
    std::string number, array;
    JsonWriter(number).value(0.25);
    EXPECT_EQ(number, nlohmann::json(0.25).dump(2));
    JsonWriter arrayWriter(array);
    arrayWriter.beginArray();
    arrayWriter.value(true);
    arrayWriter.beginArray();
    arrayWriter.endArray();
    arrayWriter.endArray();
    EXPECT_EQ(array, nlohmann::json::array({true, nlohmann::json::array()}).dump(2));
}

TEST(JsonWriter, KeysMustComeInOrderAndBePlain) {
    std::string text;
    JsonWriter json(text);
    json.beginObject();
    json.key("b");
    json.value(true);
    EXPECT_THROW(json.key("a"), std::logic_error);
    EXPECT_THROW(json.key("b"), std::logic_error);  // twice
    EXPECT_THROW(json.key("Camel"), std::logic_error);
    EXPECT_THROW(json.key("with space"), std::logic_error);
    EXPECT_THROW(json.key(""), std::logic_error);
    json.key("c");
    EXPECT_THROW(json.key("d"), std::logic_error);       // c has no value yet
    EXPECT_THROW(json.endObject(), std::logic_error);    // nor here
    json.value(size_t(1));
    EXPECT_THROW(json.value(size_t(2)), std::logic_error);  // a value without a key
    EXPECT_THROW(json.endArray(), std::logic_error);        // an object is open
    json.endObject();
    EXPECT_EQ(text, nlohmann::json({{"b", true}, {"c", 1}}).dump(2));
    EXPECT_THROW(json.endObject(), std::logic_error);       // nothing open
}

TEST(JsonWriter, KeysOnlyInsideObjects) {
    std::string text;
    JsonWriter json(text);
    EXPECT_THROW(json.key("a"), std::logic_error);
    json.beginArray();
    EXPECT_THROW(json.key("a"), std::logic_error);
    EXPECT_THROW(json.endObject(), std::logic_error);
}

}  // namespace
}  // namespace conescope
