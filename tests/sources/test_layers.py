#!/usr/bin/env python3
"""The layer rule of scripts/check-sources.py on made-up sources: an include of a layer above is a
breach (batch runs naming the command line, the core naming the readers, the window naming batch
runs), one of the same layer or below is not."""
import importlib.util
import os
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SPEC = importlib.util.spec_from_file_location("check_sources", os.path.join(HERE, "..", "..", "scripts", "check-sources.py"))
rules = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(rules)


class Layers(unittest.TestCase):
    def test_an_include_from_a_layer_above_is_a_breach(self):
        files = [("src/batch/Job.cpp", ['#include "batch/OutputFiles.h"', '#include "io/StatisticsIO.h"', '#include "cli/Batch.h"']),
                 ("src/core/Culling.cpp", ['#include "Culling.h"', '#include "core/meshopt/Meshopt.h"', '#include "io/MeshReader.h"']),
                 ("ui/Session.cpp", ['#include "scene/ClusterScene.h"', '#include "io/StatisticsIO.h"', '#include "batch/BatchJob.h"']),
                 ("tests/cli/BatchCliTests.cpp", ['#include "cli/Batch.h"'])]
        self.assertEqual(list(rules.layer_includes(files)),
                         ["src/batch/Job.cpp:3: src/batch includes cli/ (a layer above it)",
                          "src/core/Culling.cpp:3: src/core includes io/ (a layer above it)",
                          "ui/Session.cpp:3: ui includes batch/ (a layer above it)"])

    def test_the_sources_keep_it(self):
        root = os.path.join(HERE, "..", "..")
        self.assertEqual(list(rules.layer_includes(rules.source_files(root, ["src", "ui"]))), [])


if __name__ == "__main__":
    unittest.main()
