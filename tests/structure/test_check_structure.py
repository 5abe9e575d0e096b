#!/usr/bin/env python3
"""The structure checker finds what it claims to find: long functions, and only functions; includes across layers
and into the simulated backend from the runtime's API."""
import pathlib
import sys
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_structure as cs  # noqa: E402


def function(name, body_lines, qualifiers=""):
    body = "".join(f"  int v{i} = {i};\n" for i in range(body_lines))
    return f"int {name}(int a){qualifiers} {{\n{body}}}\n"


class LongFunctions(unittest.TestCase):
    def test_counts_from_brace_to_brace(self):
        # A body of 79 statements spans 81 lines with its braces.
        self.assertEqual(cs.long_functions(function("f", 79)), [(1, 81)])
        self.assertEqual(cs.long_functions(function("f", 78)), [])

    def test_qualified_members_and_trailing_returns(self):
        src = "struct S {\n" + function("f", 90, " const noexcept override") + "};\n"
        self.assertEqual(cs.long_functions(src), [(2, 92)])
        self.assertEqual(len(cs.long_functions(function("g", 90, " -> int"))), 1)

    def test_blocks_inside_a_function_are_part_of_it(self):
        inner = "  if (a) {\n" + "".join(f"    a += {i};\n" for i in range(50)) + "  }\n"
        lam = "  auto l = [](int x) {\n" + "".join(f"    x += {i};\n" for i in range(50)) + "    return x; };\n"
        src = "void f(int a) {\n" + inner + lam + "}\n"
        found = cs.long_functions(src)
        self.assertEqual(len(found), 1)
        self.assertEqual(found[0][0], 1)

    def test_braces_in_comments_strings_and_namespaces_do_not_count(self):
        src = ('namespace n {\n// void g() {\nconst char* s = "f() {";\n/* h() { */\n' + function("f", 10) + "}\n")
        self.assertEqual(cs.long_functions(src), [])
        self.assertEqual(cs.long_functions(src.replace("10", "100").replace(function("f", 10), function("f", 100))),
                         [(5, 102)])

    def test_blanking_keeps_line_numbers(self):
        text = 'a /* x\ny */ b "q\\"{" // c {\n#include "z"\nd'
        blank = cs.blank_comments_and_strings(text)
        self.assertEqual(blank.count("\n"), text.count("\n"))
        self.assertNotIn("{", blank)


class Includes(unittest.TestCase):
    def test_api_headers_must_not_include_the_simulated_backend(self):
        sim = '#include "parix/sim/simulation.hpp"\n'
        self.assertEqual(len(cs.include_problems("parix/backend.hpp", sim)), 1)
        self.assertIn("API", cs.include_problems("parix/processor.hpp", sim)[0])
        # The backend itself, its sources and other folders of parix/ may.
        self.assertEqual(cs.include_problems("parix/sim/sim_process.hpp", sim), [])
        self.assertEqual(cs.include_problems("parix/backend.cpp", sim), [])
        self.assertEqual(cs.include_problems("parix/mpi/mpi_runtime.hpp", sim), [])
        self.assertEqual(cs.include_problems("parix/backend.hpp", '#include "parix/run_result.hpp"\n'), [])

    def test_layers_go_one_way(self):
        self.assertEqual(len(cs.include_problems("machine/mesh.cpp", '#include "parix/processor.hpp"\n')), 1)
        self.assertEqual(len(cs.include_problems("parix/backend.cpp", '#include "apps/common/image.hpp"\n')), 1)
        self.assertEqual(cs.include_problems("apps/cli/main.cpp", '#include "parix/sim/simulation.hpp"\n'), [])


if __name__ == "__main__":
    unittest.main()
