#!/usr/bin/env python3
"""The function-length rule of scripts/check-sources.py on small made-up sources: it measures a
function from its signature's first line to its closing brace, counts lambdas and blocks with the
function around them, and walks through namespaces, classes and initialiser lists."""
import importlib.util
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SPEC = importlib.util.spec_from_file_location("check_sources", os.path.join(HERE, "..", "..", "scripts", "check-sources.py"))
rules = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(rules)


def body(count):
    return [f"    total += {i};" for i in range(count)]


class FunctionLength(unittest.TestCase):
    def spans(self, text):
        return list(rules.function_spans(text.split("\n")))

    def test_a_function_spans_its_signature_and_closing_brace(self):
        source = "namespace n {\n\nint sum(int a,\n        int b) {\n    int total = 0;\n    return total;\n}\n\n}  // namespace n\n"
        self.assertEqual(self.spans(source), [("sum", 3, 7)])

    def test_lambdas_blocks_braces_in_strings_and_comments_stay_in_their_function(self):
        source = "\n".join(["void run() {", "    auto f = [](int x) {", "        if (x) { return '{'; }",
                            '        return "}}";  // }', "    };", "    /* { */", "}", "int after() { return 1; }"])
        self.assertEqual(self.spans(source), [("run", 1, 7), ("after", 8, 8)])

    def test_classes_member_functions_and_initialisers(self):
        source = "\n".join(["class Widget : public Base {", "    Q_OBJECT", "public:", "    explicit Widget(int v)",
                            "        : value_{v}, other_(2) {", "        setUp();", "    }", "    int value() const { return value_; }",
                            "private:", "    int value_{0};", "};", "const std::vector<int> table = {", "    1, 2,", "};",
                            "enum class Kind : int { a, b };", "auto Widget::make() -> std::vector<int> {", "    return {};", "}",
                            "bool Widget::operator()(int a) const { return a; }", "Widget operator+(Widget a, Widget b) { return a; }"])
        self.assertEqual(self.spans(source), [("Widget", 4, 7), ("value", 8, 8), ("Widget::make", 16, 18),
                                              ("Widget::operator()", 19, 19), ("operator+", 20, 20)])

    def test_lambdas_in_a_table_at_namespace_scope_count_from_their_own_line(self):
        source = "\n".join(["const Column columns[] = {", "    {\"a\", 1},", "    {\"b\",", "     [](int c) {", "         return c;",
                            "     }},", "};"])
        self.assertEqual(self.spans(source), [("lambda", 4, 6)])

    def test_a_long_function_is_a_breach_and_a_short_one_or_an_allowed_one_is_not(self):
        limit = rules.MAX_FUNCTION_LINES
        long_function = ["int tooLong() {", "    int total = 0;", *body(limit - 3), "    return total;", "}"]
        at_limit = ["int justRight() {", *body(limit - 2), "}"]
        self.assertEqual(len(long_function), limit + 1)
        files = [("src/core/A.cpp", long_function + at_limit + [""]), ("tests/core/B.cpp", long_function)]
        breaches = list(rules.long_functions(files, allowed={}))
        self.assertEqual(len(breaches), 1)
        self.assertIn("src/core/A.cpp:1: tooLong runs 81 lines", breaches[0])
        self.assertEqual(list(rules.long_functions(files, allowed={("src/core/A.cpp", "tooLong"): "why"})), [])


if __name__ == "__main__":
    unittest.main()
