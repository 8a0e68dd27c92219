// Test helper: the comma-separated cells of one CSV line (no quoting: the
// package's CSV files hold numbers only).
#ifndef TILABLE_SURFACES_TEST_CSV_CELLS_H
#define TILABLE_SURFACES_TEST_CSV_CELLS_H

#include <sstream>
#include <string>
#include <vector>

inline std::vector<std::string> csv_cells(const std::string& line)
{
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while(std::getline(in, cell, ',')) cells.push_back(cell);
  return cells;
}

#endif
