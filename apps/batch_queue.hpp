// A small blocking queue with a capacity, between the batch worker's loader,
// renderer and writer threads: a full queue makes the producer wait, so the
// meshes loaded ahead and the images waiting to be written stay bounded.
#ifndef PHONGRAST_APPS_BATCH_QUEUE_HPP
#define PHONGRAST_APPS_BATCH_QUEUE_HPP

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <utility>

namespace phongrast::cli {

template <typename Item>
class BoundedQueue {
public:
    explicit BoundedQueue(std::size_t capacity) : capacity_(capacity) {}

    void push(Item item) {
        std::unique_lock<std::mutex> lock(mutex_);
        not_full_.wait(lock, [&] { return items_.size() < capacity_; });
        items_.push_back(std::move(item));
        not_empty_.notify_one();
    }

    Item pop() {
        std::unique_lock<std::mutex> lock(mutex_);
        not_empty_.wait(lock, [&] { return !items_.empty(); });
        Item item = std::move(items_.front());
        items_.pop_front();
        not_full_.notify_one();
        return item;
    }

private:
    std::size_t capacity_;
    std::deque<Item> items_;
    std::mutex mutex_;
    std::condition_variable not_full_;
    std::condition_variable not_empty_;
};

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_QUEUE_HPP
