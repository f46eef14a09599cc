// SPDX-License-Identifier: BSD-3-Clause
#error "a public kinestat header includes <SuiteSparseQR.hpp>, a private dependency"
