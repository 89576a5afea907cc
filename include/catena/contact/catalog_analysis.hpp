// `catalog`: list, show and search the ISO 606 chain catalogue (data/catalog/iso606/) with each
// row's sources. A lookup, not a model: it has no chain type, so case files do not run it; the
// command line and Python reach it through the registry like every analysis.
#pragma once

#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/contact/chain_catalog.hpp"

namespace catena::contact {

/// The rows `catalog` selected: one chain (--chain), the matches of --search, or all.
struct CatalogAnalysis {
  bool single = false;
  std::vector<ChainDimensions> chains;
};

const analysis::Analysis& catalog_analysis();
CatalogAnalysis catalog_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::contact
