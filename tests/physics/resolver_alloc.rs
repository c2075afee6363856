//! The resolver's fast path allocates nothing per iteration: everything is
//! allocated at prepare. A counting global allocator (this test binary's
//! own) counts the allocations of the test's own thread during each phase
//! (the test harness allocates on other threads).

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use contact_lab::physics::params::ResolverParams;
use contact_lab::physics::resolver::{row::sphere_row, Implementation, Resolver, Silent};

struct Counting;

thread_local! {
    // Const-initialised and without a destructor: touching it never allocates.
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
}

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn phases_allocate_nothing() {
    let world = sphere_row::<f64>(50);
    for implementation in [Implementation::Scan, Implementation::Indexed] {
        let mut r = Resolver::prepare(&world, &ResolverParams::default());
        let before = allocations();
        let position = r.position_phase(implementation, &mut Silent);
        let velocity = r.velocity_phase(implementation, &mut Silent);
        let during = allocations() - before;
        // The phases did work, and none of it allocated.
        assert!(position.iterations_used > 100, "{position:?}");
        assert!(velocity.iterations_used > 50, "{velocity:?}");
        assert_eq!(
            during, 0,
            "{implementation:?}: allocations during the phases"
        );
    }
}
