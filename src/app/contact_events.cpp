#include "app/contact_events.hpp"

namespace kiln
{
void ContactEvents::start(const int n_active, const int n_loaded)
{
  last_active_ = n_active;
  last_loaded_ = n_loaded;
  closed_.clear();
  opened_.clear();
}

void ContactEvents::step(const double time, const int n_rows, const int n_active,
                         const int n_loaded)
{
  if (last_active_ >= 0 && n_active == n_rows && last_active_ < n_rows)
    closed_.push_back(time);
  if (last_loaded_ > 0 && n_loaded == 0)
    opened_.push_back(time);
  last_active_ = n_active;
  last_loaded_ = n_loaded;
}
} // namespace kiln
