//! The command's memory allocator: small blocks from mimalloc, large ones from the system's.
//!
//! Why two: a batch of small polygons makes many small allocations per polygon (positions read,
//! the steps' short lists), which a thread-caching allocator (jemalloc first, mimalloc since:
//! as fast here, and built from one C file instead of a `configure` run) serves faster than
//! glibc's `malloc`. But with such an allocator alone, polygons of 10^6 vertices ran slower:
//! large blocks are returned to the system and faulted in again, and a `Vec` doubling to
//! millions of elements is copied where glibc's `realloc` moves pages (`mremap`). The figures:
//! docs/benchmarks.md ("Figures behind the code's constants and choices"). So a block of
//! [`LARGE`] bytes or more comes from the system's allocator, anything smaller from mimalloc.
//!
//! Soundness: `dealloc` and `realloc` are given the block's layout, so the size the block was
//! allocated with tells which allocator owns it; a `realloc` across the threshold allocates in
//! the other allocator, copies and frees (as `GlobalAlloc::realloc`'s default does).

use mimalloc::MiMalloc;
use std::alloc::{GlobalAlloc, Layout, System};

/// The smallest block taken from the system's allocator (glibc serves blocks this large with
/// `mmap` from 128 KiB up anyway, and moves them on `realloc`).
pub const LARGE: usize = 64 * 1024;

/// Small blocks from mimalloc, large ones from the system (module doc).
pub struct Split;

fn small(layout: Layout) -> bool {
    layout.size() < LARGE
}

// SAFETY: every block is freed and reallocated by the allocator that made it (decided by the
// size in its layout, which the caller must pass unchanged, as `GlobalAlloc` requires).
unsafe impl GlobalAlloc for Split {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if small(layout) {
            MiMalloc.alloc(layout)
        } else {
            System.alloc(layout)
        }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if small(layout) {
            MiMalloc.alloc_zeroed(layout)
        } else {
            System.alloc_zeroed(layout)
        }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        if small(layout) {
            MiMalloc.dealloc(ptr, layout)
        } else {
            System.dealloc(ptr, layout)
        }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY (of `from_size_align_unchecked`): the caller guarantees that `new_size`,
        // rounded up to `layout.align()`, does not overflow `isize`.
        let new_layout = Layout::from_size_align_unchecked(new_size, layout.align());
        match (small(layout), small(new_layout)) {
            (true, true) => MiMalloc.realloc(ptr, layout, new_size),
            (false, false) => System.realloc(ptr, layout, new_size),
            _ => {
                let new = self.alloc(new_layout);
                if !new.is_null() {
                    std::ptr::copy_nonoverlapping(ptr, new, layout.size().min(new_size));
                    self.dealloc(ptr, layout);
                }
                new
            }
        }
    }
}
