#error "a public kinestat header includes <cholmod.h>, a private dependency"
