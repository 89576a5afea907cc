// The registry: one line per analysis. A model added to Catena is listed here and nowhere else.
#include <algorithm>
#include <stdexcept>

#include "catena/catena.hpp"
#include "catena/composite/analysis.hpp"
#include "catena/contact/analysis.hpp"
#include "catena/contact/catalog_analysis.hpp"
#include "catena/drive/analysis.hpp"
#include "catena/drive/drive_analysis.hpp"
#include "catena/dynamics/analysis.hpp"
#include "catena/engagement/analysis.hpp"
#include "catena/hinge/analysis.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/pocketwheel/analysis.hpp"
#include "catena/strength/analysis.hpp"
#include "catena/strength/loop_analysis.hpp"
#include "catena/warp/analysis.hpp"
#include "catena/wear/analysis.hpp"

namespace catena {

const std::vector<const analysis::Analysis*>& analyses() {
  static const std::vector<const analysis::Analysis*> all = {
      &pocketwheel::run_on_analysis(),
      &hinge::hinge_analysis(),
      &hinge::sweep_analysis(),
      &contact::contact_analysis(),
      &contact::fretting_analysis(),
      &engagement::engagement_analysis(),
      &warp::warp_analysis(),
      &composite::ring_analysis(),
      &composite::ring_capacity_analysis(),
      &composite::ring_design_analysis(),
      &strength::loop_analysis(),
      &strength::strength_analysis(),
      &drive::sprocket_analysis(),
      &contact::catalog_analysis(),
      &drive::drive_analysis(),
      &drive::drive_select_analysis(),
      &wear::wear_analysis(),
      &dynamics::dynamics_analysis(),
  };
  return all;
}

const analysis::Analysis* find_analysis(std::string_view name) {
  for (const analysis::Analysis* a : analyses()) {
    if (a->name == name) return a;
  }
  return nullptr;
}

analysis::Record run(std::string_view name,
                     const std::vector<std::pair<std::string, std::string>>& inputs,
                     const Progress* progress) {
  const analysis::Analysis* a = find_analysis(name);
  if (a == nullptr) throw InputError({{"analysis", std::string(name), "an analysis Catena has"}});
  std::vector<Issue> issues;
  std::vector<std::string> unread;  // table parameters whose file could not be read
  std::vector<io::RawInput> raw = io::raw_inputs(*a, inputs, issues, unread);
  return io::bind_and_evaluate(*a, raw, std::move(issues), unread, progress);
}

}  // namespace catena
