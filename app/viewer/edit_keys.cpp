#include "edit_keys.hpp"

#include "viewer.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

void edit_key(Viewer& v, EditKey key) {
  WorkbenchHost* host = v.workbench;
  if (!host) return v.notify("editing: not in this window");
  switch (key) {
    case EditKey::toggle:
      if (const std::string why = host->toggle(&v.session()); !why.empty()) v.notify(why);
      return;
    case EditKey::new_input: return host->start_new();
    case EditKey::save: return v.notify(host->save());
    case EditKey::undo:
    case EditKey::redo:
    case EditKey::erase:
    case EditKey::region_box:
    case EditKey::region_lasso:
      if (!host->bench() || !host->editing) return v.notify("nothing is being edited: E starts editing this run's input");
      if (key == EditKey::undo) host->undo();
      else if (key == EditKey::redo) host->redo();
      else if (key == EditKey::erase) delete_selected(*host);
      else choose_region_shape(*host, key == EditKey::region_lasso);
      return;
  }
}

}  // namespace meshstep::viewer
