// Vectors whose elements start unwritten: for the loader's large temporaries that a parallel pass
// fills whole right after they are made. Their large blocks are scratch pages (scratch_pages.h).
#pragma once

#include "geometry/scene/scratch_pages.h"

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace geometry::scene {

/// ScratchAllocator, except that making an element with no value default-initialises it: a trivial
/// element is left unwritten. std::vector's sized constructor and resize() would otherwise zero
/// every byte on one thread, taking every fresh page's fault there, before a parallel pass writes
/// them all again; left unwritten, the threads of that pass fault their own pages in.
template <class T> struct DefaultInitAllocator : ScratchAllocator<T> {
    using value_type = T;
    template <class U> struct rebind { using other = DefaultInitAllocator<U>; };
    DefaultInitAllocator() noexcept = default;
    template <class U> DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
    template <class U> void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args> void construct(U* p, Args&&... args) {
        std::construct_at(p, std::forward<Args>(args)...);
    }
};

/// A vector of trivial elements that the code writes in full before reading any.
template <class T> using UnwrittenVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace geometry::scene
