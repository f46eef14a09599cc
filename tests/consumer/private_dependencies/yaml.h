#error "a public kinestat header includes <yaml.h> (libyaml), a private dependency"
