#error "a public kinestat header includes <SuiteSparseQR.hpp>, a private dependency"
