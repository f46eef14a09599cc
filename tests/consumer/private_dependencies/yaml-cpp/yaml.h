#error "a public kinestat header includes <yaml-cpp/yaml.h>, a private dependency"
