// A numeric table compiled into core from a CSV file of core/data/ (core/data/embed_csv.cmake), read-only: rows of
// `columns` numbers, the first column the abscissa, ascending (the wavelength in nm for the spectra; the Beckmann
// sigma, outermost of three grid columns, for the microsurface's table).
#pragma once

#include <span>
#include <string_view>

namespace skinlayer::data {

struct EmbeddedTable {
  std::span<const double> values;  // row-major
  int columns = 0;
  std::string_view header;  // the CSV's header row

  int rows() const { return static_cast<int>(values.size()) / columns; }
  double at(int row, int column) const { return values[static_cast<std::size_t>(row * columns + column)]; }
  // Linear interpolation of `column` at abscissa x (clamped to the table's range).
  double interpolate(int column, double x) const;
};

// core/data/hemoglobin_prahl.csv: wavelength_nm, HbO2 and Hb molar extinction in cm^-1 / (mol/L).
EmbeddedTable hemoglobin_prahl();
// core/data/cie1931_2deg_cmf.csv: wavelength_nm, xbar, ybar, zbar (CIE 1931 2-degree observer), 1 nm steps.
EmbeddedTable cie1931_2deg_cmf();
// core/data/cie_d65.csv: wavelength_nm, relative spectral power of CIE D65 (100 at 560 nm), 1 nm steps.
EmbeddedTable cie_d65();
// core/data/microfacet_multiple_scattering.csv: sigma, E, kernel, theta_i, theta_o, unit, then the multiply scattered
// lobe's shape at the header's azimuths, in units; core/data/microfacet_single_scattering_loss.csv: sigma, E, side,
// then the single scattering's loss at polar angles 0 to 90 degrees. See core/interfaces/multiple_scattering_table.h.
EmbeddedTable microfacet_multiple_scattering();
EmbeddedTable microfacet_single_scattering_loss();

}  // namespace skinlayer::data
