// SPDX-License-Identifier: BSD-3-Clause
#error "a public kinestat header includes <cholmod.h>, a private dependency"
