// Checkpoint state of the crack laws whose cells hold one value per column.
#include <stdexcept>
#include <string>

#include "vibrotherm/contact/crack_law.hpp"

namespace vibrotherm::contact {

std::vector<double> save_cell_values(std::size_t cell, std::initializer_list<const std::vector<double>*> columns) {
  std::vector<double> values;
  for (const std::vector<double>* column : columns) values.push_back((*column)[cell]);
  return values;
}

void restore_cell_values(std::size_t cell, const double* values, std::size_t n,
                         std::initializer_list<std::vector<double>*> columns) {
  if (n != columns.size())
    throw std::runtime_error("crack law: a saved cell state has " + std::to_string(n) + " values, expected " +
                             std::to_string(columns.size()));
  for (std::vector<double>* column : columns) (*column)[cell] = *values++;
}

}  // namespace vibrotherm::contact
