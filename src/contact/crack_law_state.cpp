// Checkpoint state of the crack laws whose cells hold numbers and tangential vectors.
#include <stdexcept>
#include <string>

#include "vibrotherm/contact/crack_law.hpp"

namespace vibrotherm::contact {

std::vector<double> save_cell_state(std::initializer_list<double> numbers, std::initializer_list<Tangential> vectors) {
  std::vector<double> values(numbers);
  for (const Tangential& v : vectors)
    for (int k = 0; k < v.components(); ++k) values.push_back(v[k]);
  return values;
}

void restore_cell_state(const double* values, std::size_t n, std::initializer_list<double*> numbers,
                        std::initializer_list<Tangential*> vectors) {
  std::size_t expected = numbers.size();
  for (const Tangential* v : vectors) expected += v->components();
  if (n != expected)
    throw std::runtime_error("crack law: a saved cell state has " + std::to_string(n) + " values, expected " +
                             std::to_string(expected));
  for (double* x : numbers) *x = *values++;
  for (Tangential* v : vectors)
    for (int k = 0; k < v->components(); ++k) (*v)[k] = *values++;
}

}  // namespace vibrotherm::contact
