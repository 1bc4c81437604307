//! The wrapper every run-time call shares: check the caller's slices, copy
//! them into the class's arrays, run the class's algorithm, and tell its
//! error in the caller's terms.

/// One call of a run-time model method:
///
/// ```text
/// class_call!(self, ws, "rnea",
///     inputs: [q, "v" => v, "a" => a],
///     checks: [self.check_nv("tau", tau)],
///     |m, s| rnea(&m.model, &mut s.data, &s.q, &s.v, &s.a, None).map(|out| ...))
/// ```
///
/// checks `q` (`nq` entries) and each named input (`nv` entries), then the
/// further `checks` (outputs, settings) in order, then binds any `let`s;
/// in the class, copies `q` and the named inputs (the first into `v`, the
/// second into `a`) and runs the body, a `rodyn::Result`, whose error
/// names the algorithm and the faulty input.
macro_rules! class_call {
    (
        $model:expr, $ws:expr, $algorithm:expr,
        inputs: [$q:expr $(, $name:literal => $x:expr)* $(,)?],
        checks: [$($check:expr),* $(,)?],
        $(let $binding:pat = $value:expr;)*
        |$m:ident, $s:ident| $body:expr
    ) => {{
        $model.check_q($q)?;
        $($model.check_nv($name, $x)?;)*
        $($check?;)*
        $(let $binding = $value;)*
        let inputs = [
            $crate::runtime::check::Input { name: "q", values: $q },
            $($crate::runtime::check::Input { name: $name, values: $x },)*
        ];
        dispatch!(&$model.class, &mut $ws.class, |$m, $s| {
            let $s = &mut **$s;
            $s.set_q($q);
            $s.set_rates(&[$(&$x[..]),*]);
            let result: rodyn::Result<_> = $body;
            result.map_err(|e| $model.explain($algorithm, &e, &inputs))
        })
    }};
}
