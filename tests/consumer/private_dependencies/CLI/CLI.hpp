#error "a public kinestat header includes <CLI/CLI.hpp>, a private dependency"
