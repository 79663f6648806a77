//! C ABI over kurbo 0.7 and lyon_geom 0.15, used as benchmark peers by the
//! C++ Google Benchmark binaries. The contract of each function is in
//! ../rust_peers.h. Every entry point catches panics (NaN / 0 on panic) and
//! allocates nothing itself; it must build with Debian bookworm's rustc 1.63.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::slice;

use kurbo::{CubicBez, Line, ParamCurveArclen, ParamCurveNearest, PathSeg, Point};
use lyon_geom::euclid::point2 as lpoint;
use lyon_geom::CubicBezierSegment;

fn kcubic(p: &[f64]) -> CubicBez {
    CubicBez::new(
        Point::new(p[0], p[1]),
        Point::new(p[2], p[3]),
        Point::new(p[4], p[5]),
        Point::new(p[6], p[7]),
    )
}

fn lcubic(p: &[f64]) -> CubicBezierSegment<f64> {
    CubicBezierSegment {
        from: lpoint(p[0], p[1]),
        ctrl1: lpoint(p[2], p[3]),
        ctrl2: lpoint(p[4], p[5]),
        to: lpoint(p[6], p[7]),
    }
}

/// A slice of `len` values at `ptr`; empty for len 0 (ptr may then be null).
unsafe fn view<'a, T>(ptr: *const T, len: usize) -> &'a [T] {
    if len == 0 || ptr.is_null() {
        &[]
    } else {
        slice::from_raw_parts(ptr, len)
    }
}

unsafe fn view_mut<'a, T>(ptr: *mut T, len: usize) -> &'a mut [T] {
    if len == 0 || ptr.is_null() {
        &mut []
    } else {
        slice::from_raw_parts_mut(ptr, len)
    }
}

/// Runs `f`, or gives `on_panic` if it panicked.
fn guarded<R, F: FnOnce() -> R>(on_panic: R, f: F) -> R {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(on_panic)
}

#[no_mangle]
pub unsafe extern "C" fn casteljau_kurbo_cubic_arclen(p: *const f64, accuracy: f64) -> f64 {
    if p.is_null() {
        return f64::NAN;
    }
    let p = view(p, 8);
    guarded(f64::NAN, || kcubic(p).arclen(accuracy))
}

#[no_mangle]
pub unsafe extern "C" fn casteljau_kurbo_cubic_inv_arclen(
    p: *const f64,
    length: f64,
    accuracy: f64,
) -> f64 {
    if p.is_null() {
        return f64::NAN;
    }
    let p = view(p, 8);
    guarded(f64::NAN, || kcubic(p).inv_arclen(length, accuracy))
}

#[no_mangle]
pub unsafe extern "C" fn casteljau_kurbo_cubic_nearest(
    p: *const f64,
    queries: *const f64,
    n: usize,
    accuracy: f64,
    out_t: *mut f64,
    out_distance_squared: *mut f64,
) {
    let ts = view_mut(out_t, n);
    let ds = view_mut(out_distance_squared, n);
    if p.is_null() || queries.is_null() || ts.len() != n || ds.len() != n {
        return;
    }
    let p = view(p, 8);
    let q = view(queries, 2 * n);
    let ok = guarded(false, || {
        let c = kcubic(p);
        for i in 0..n {
            let (t, d2) = c.nearest(Point::new(q[2 * i], q[2 * i + 1]), accuracy);
            ts[i] = t;
            ds[i] = d2;
        }
        true
    });
    if !ok {
        let ts = view_mut(out_t, n);
        let ds = view_mut(out_distance_squared, n);
        ts.iter_mut().for_each(|v| *v = f64::NAN);
        ds.iter_mut().for_each(|v| *v = f64::NAN);
    }
}

#[no_mangle]
pub unsafe extern "C" fn casteljau_kurbo_path_arclen(
    cubics: *const f64,
    count: usize,
    accuracy: f64,
) -> f64 {
    if count != 0 && cubics.is_null() {
        return f64::NAN;
    }
    let c = view(cubics, 8 * count);
    guarded(f64::NAN, || {
        c.chunks_exact(8).map(|piece| kcubic(piece).arclen(accuracy)).sum()
    })
}

#[no_mangle]
pub unsafe extern "C" fn casteljau_kurbo_path_nearest(
    cubics: *const f64,
    count: usize,
    queries: *const f64,
    n: usize,
    accuracy: f64,
    out_piece: *mut usize,
    out_t: *mut f64,
    out_distance_squared: *mut f64,
) {
    let pieces = view_mut(out_piece, n);
    let ts = view_mut(out_t, n);
    let ds = view_mut(out_distance_squared, n);
    if queries.is_null() || pieces.len() != n || ts.len() != n || ds.len() != n {
        return;
    }
    let c = view(cubics, 8 * count);
    let q = view(queries, 2 * n);
    let ok = count != 0
        && c.len() == 8 * count
        && guarded(false, || {
            for i in 0..n {
                let pt = Point::new(q[2 * i], q[2 * i + 1]);
                let mut best = (usize::MAX, f64::NAN, f64::INFINITY);
                for (k, piece) in c.chunks_exact(8).enumerate() {
                    let (t, d2) = kcubic(piece).nearest(pt, accuracy);
                    if d2 < best.2 {
                        best = (k, t, d2);
                    }
                }
                pieces[i] = best.0;
                ts[i] = best.1;
                ds[i] = best.2;
            }
            true
        });
    if !ok {
        let pieces = view_mut(out_piece, n);
        let ts = view_mut(out_t, n);
        let ds = view_mut(out_distance_squared, n);
        pieces.iter_mut().for_each(|v| *v = usize::MAX);
        ts.iter_mut().for_each(|v| *v = f64::NAN);
        ds.iter_mut().for_each(|v| *v = f64::NAN);
    }
}

#[no_mangle]
pub unsafe extern "C" fn casteljau_lyon_cubic_intersections(
    a: *const f64,
    b: *const f64,
    out_ta: *mut f64,
    out_tb: *mut f64,
    capacity: usize,
) -> usize {
    if a.is_null() || b.is_null() {
        return 0;
    }
    let a = view(a, 8);
    let b = view(b, 8);
    let ta = view_mut(out_ta, capacity);
    let tb = view_mut(out_tb, capacity);
    let room = ta.len().min(tb.len());
    guarded(0, || {
        let found = lcubic(a).cubic_intersections_t(&lcubic(b));
        for (i, &(s, t)) in found.iter().take(room).enumerate() {
            ta[i] = s;
            tb[i] = t;
        }
        found.len()
    })
}

#[no_mangle]
pub unsafe extern "C" fn casteljau_kurbo_cubic_line_intersections(
    p: *const f64,
    line: *const f64,
    out_t_curve: *mut f64,
    out_t_line: *mut f64,
    capacity: usize,
) -> usize {
    if p.is_null() || line.is_null() {
        return 0;
    }
    let p = view(p, 8);
    let l = view(line, 4);
    let tc = view_mut(out_t_curve, capacity);
    let tl = view_mut(out_t_line, capacity);
    let room = tc.len().min(tl.len());
    guarded(0, || {
        let seg = PathSeg::Cubic(kcubic(p));
        let found = seg.intersect_line(Line::new((l[0], l[1]), (l[2], l[3])));
        for (i, x) in found.iter().take(room).enumerate() {
            tc[i] = x.segment_t;
            tl[i] = x.line_t;
        }
        found.len()
    })
}
