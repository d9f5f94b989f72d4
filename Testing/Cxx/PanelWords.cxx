// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The core's word rule as a program, for the WordRules test
// (Python/filter/test_word_rules.py): reads texts from its input, one after
// another with a NUL byte between them, and writes nv::InPanelWords of each,
// separated alike.
#include "nvReconstruct.h"

#include <iostream>
#include <iterator>
#include <string>

int main()
{
  const std::string input((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  for (std::size_t start = 0;;)
  {
    const std::size_t end = input.find('\0', start);
    std::cout << nv::InPanelWords(input.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos)
    {
      break;
    }
    std::cout << '\0';
    start = end + 1;
  }
  return std::cout.good() ? 0 : 1;
}
