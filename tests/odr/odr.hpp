// SPDX-License-Identifier: BSL-1.0
#pragma once
bool rejects_with_checks_on();
bool rejects_with_checks_off();
