#pragma once
// What one run computes once and several of its parts read: Table 1's convention search (the table1
// section and four of the paper's claims), a grid lemma's premise (a claim judged again for a
// consequence or for the paper's earlier text). The run owns its memo and passes it by pointer
// (run_context::memo, a section's settings); nothing is remembered across runs or by the process, so
// two runs in one process (a test, `compare`) never see each other's values.

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <typeinfo>
#include <utility>

namespace simpson::verify {

class run_memo {
 public:
  /// The value stored under `key` (and the type T), or `compute()`'s, stored. Two threads asking for
  /// one key at once may both compute it; the first stored is kept (a memo of pure functions only).
  template <class T, class F>
  T remember(const std::string& key, F&& compute) {
    const std::string typed = std::string(typeid(T).name()) + '\x1f' + key;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto it = values_.find(typed);
      if (it != values_.end()) return *std::static_pointer_cast<const T>(it->second);
    }
    auto value = std::make_shared<const T>(std::forward<F>(compute)());
    std::lock_guard<std::mutex> lock(mutex_);
    return *std::static_pointer_cast<const T>(values_.emplace(typed, std::move(value)).first->second);
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const void>> values_;
};

/// `memo->remember<T>(key, compute)`, or `compute()` when there is no memo (a check run on its own).
template <class T, class F>
T remembered(run_memo* memo, const std::string& key, F&& compute) {
  if (memo == nullptr) return std::forward<F>(compute)();
  return memo->remember<T>(key, std::forward<F>(compute));
}

}  // namespace simpson::verify
