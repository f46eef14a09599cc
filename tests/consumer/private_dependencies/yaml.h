// SPDX-License-Identifier: BSD-3-Clause
#error "a public kinestat header includes <yaml.h> (libyaml), a private dependency"
