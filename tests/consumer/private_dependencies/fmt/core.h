#error "a public kinestat header includes <fmt/core.h>, a private dependency"
