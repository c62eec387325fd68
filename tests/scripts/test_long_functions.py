"""scripts/long_functions.py: what its scan counts as a function, and its length.

    /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import importlib.util
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "long_functions.py")
_spec = importlib.util.spec_from_file_location("long_functions", SCRIPT)
long_functions = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(long_functions)


def functions(text):
    return [(name, last - first + 1) for name, first, last in long_functions.scan(text)]


class Scan(unittest.TestCase):
    def test_signature_to_closing_brace(self):
        text = ("// a comment above is not counted\n"
                "template <typename T>\n"
                "int twice(T x,\n"
                "          int y) {\n"
                "  return 2 * x + y;\n"
                "}\n")
        self.assertEqual(functions(text), [("twice", 5)])

    def test_lambdas_and_local_classes_belong_to_their_function(self):
        text = ("void outer() {\n"
                "  auto f = [](int a) { return a; };\n"
                "  struct Local { int g() { return 1; } };\n"
                "  if (f(1)) { for (;;) { break; } }\n"
                "}\n")
        self.assertEqual(functions(text), [("outer", 5)])

    def test_namespaces_classes_and_members(self):
        text = ("namespace a { namespace {\n"
                "class C : public B<int> {\n"
                " public:\n"
                "  C() : x_{1}, y_(2) {\n"
                "    x_ = 3;\n"
                "  }\n"
                "  int get() const { return x_; }\n"
                " private:\n"
                "  int x_{0}, y_;\n"
                "};\n"
                "int C2::set(int v) noexcept { return v; }\n"
                "}  // namespace\n"
                "}  // namespace a\n")
        self.assertEqual(functions(text), [("C", 3), ("get", 1), ("C2::set", 1)])

    def test_braces_in_literals_comments_and_default_arguments(self):
        text = ('const char* s = "{";\n'
                "/* { */\n"
                "char c = '{';\n"
                "int table[] = {1, 2, 3};\n"
                "void f(const std::string& prefix = {}) {\n"
                '  g(R"({)", 1\'000);  // }\n'
                "}\n")
        self.assertEqual(functions(text), [("f", 3)])

    def test_prefixed_raw_and_unterminated_literals(self):
        text = ("char16_t c = u'{';\n"
                "auto s = u8\"}\";\n"
                "auto r = u8R\"x({)x\";\n"
                "wchar_t w = L'}';\n"
                "auto q = LR\"(})\";\n"
                "long big = 0x1'0000'0000;\n"
                "void f() {\n"
                "  g(U'{', uR\"(}})\");\n"
                "}\n"
                "#error a stray \" ends at its line\n"
                "int h() { return '}\n"
                "; }\n")
        self.assertEqual(functions(text), [("f", 3), ("h", 2)])

    def test_only_the_first_branch_of_a_conditional(self):
        text = ("#if defined(A)\n"
                "void f(int a) {\n"
                "#elif defined(B)\n"
                "void f(long a) {\n"
                "#else\n"
                "void f() {\n"
                "#  if C\n"
                "  {\n"
                "#  endif\n"
                "#endif\n"
                "  g();\n"
                "}\n"
                "#ifdef D\n"
                "void k() { }\n"
                "#endif\n")
        self.assertEqual(functions(text), [("f", 11), ("k", 1)])

    def test_lambdas_outside_functions_are_functions(self):
        text = ("const auto table = [] {\n"
                "  return 1;\n"
                "}();\n"
                "const bool registered = registry::add(\"x\", [](int a) -> int {\n"
                "  return a;\n"
                "});\n"
                "void f() {\n"
                "  auto g = [] { return 2; };\n"
                "}\n"
                "C::C() : f_([this](int a) {\n"
                "  return a;\n"
                "}) {}\n"
                "int a[2] {1, 2};\n"
                "[[nodiscard]] int h() { return a[0]; }\n")
        self.assertEqual(functions(text), [("lambda (table)", 3), ("lambda (argument of registry::add)", 3),
                                           ("f", 3), ("C::C", 3), ("h", 1)])

    def test_names_past_templates_and_of_call_operators(self):
        text = ("template <typename T, typename = std::enable_if_t<(sizeof(T) > 4)>>\n"
                "bool Less::operator()(T a, T b) const {\n"
                "  return a < b;\n"
                "}\n"
                "std::function<double(double)> curve_of(int k) { return {}; }\n"
                "template <> Fields blank<Fields>() { return {}; }\n"
                "__attribute__((target(\"avx2\"))) void fast(double* x) { }\n"
                "Quantity::operator bool() const { return true; }\n"
                "double& V::operator[](std::size_t i) { return v_[i]; }\n")
        self.assertEqual([name for name, _ in functions(text)],
                         ["Less::operator()", "curve_of", "blank<Fields>", "fast", "Quantity::operator bool",
                          "V::operator[]"])

    def test_unbalanced_braces(self):
        for text, line in (("void f() {\n  g();\n}\n}\n", 4), ("namespace a {\nvoid f() {\n}\n", 1),
                           ("int x = g({1,\n 2);\n", 1)):
            with self.assertRaises(long_functions.Unbalanced) as caught:
                long_functions.scan(text)
            self.assertEqual(caught.exception.line, line)
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "good.cpp"), "w") as f:
                f.write("void good() { }\n")
            with open(os.path.join(tmp, "bad.cpp"), "w") as f:
                f.write("void bad() {\n  g();\n")
            run = subprocess.run([sys.executable, SCRIPT, tmp], capture_output=True, text=True)
            self.assertEqual(run.returncode, 2)
            self.assertIn("bad.cpp:1: the braces do not balance", run.stderr)
            self.assertNotIn("good.cpp", run.stderr)

    def test_all_and_utf8(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "a.cpp"), "w", encoding="utf-8") as f:
                f.write("// Fischer–Burmeister, ϑ in °C\n"
                        "void short_one() { y(); }\n"
                        "void long_one() {\n" + "  x();\n" * 5 + "}\n")
            # Read as UTF-8 whatever the locale says.
            env = dict(os.environ, LC_ALL="C", PYTHONUTF8="0", PYTHONCOERCECLOCALE="0")
            run = subprocess.run([sys.executable, SCRIPT, "--all", "--function-lines", "2", tmp],
                                 capture_output=True, text=True, env=env)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertEqual(run.stdout.splitlines(), [f"{tmp}/a.cpp:3: long_one: 7 lines",
                                                       f"{tmp}/a.cpp:2: short_one: 1 lines"])

    def test_offenders_and_status(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "a.cpp"), "w") as f:
                f.write("void long_one() {\n" + "  x();\n" * 5 + "}\n" + "void short_one() { y(); }\n")
            run = subprocess.run([sys.executable, SCRIPT, "--function-lines", "6", "--file-lines", "7", tmp],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 1)
            self.assertIn("a.cpp:1: long_one: 7 lines", run.stdout)
            self.assertIn("a.cpp: 8 lines (file)", run.stdout)
            self.assertNotIn("short_one", run.stdout)
            run = subprocess.run([sys.executable, SCRIPT, "--function-lines", "7", "--file-lines", "8", tmp],
                                 capture_output=True, text=True)
            self.assertEqual((run.returncode, run.stdout), (0, ""))


if __name__ == "__main__":
    unittest.main()
