// SPDX-License-Identifier: BSD-3-Clause
#error "a public kinestat header includes <CLI/CLI.hpp>, a private dependency"
