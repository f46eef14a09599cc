// SPDX-License-Identifier: BSD-3-Clause
#error "a public kinestat header includes <fmt/format.h>, a private dependency"
