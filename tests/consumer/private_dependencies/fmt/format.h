#error "a public kinestat header includes <fmt/format.h>, a private dependency"
