//! Unit tests of [`super`], kept beside it so that the module stays short.
use super::*;

fn read(text: &str) -> Result<CaseFile, ExchangeError> {
    read_case("d/c.csv", "c", text, Want::Results)
}

#[test]
fn element_profiles_are_grouped_by_time_and_sorted_by_position() {
    let f = read("t,x_left,x_right,stress\n0.5,0.5,1,2\n0.5,0,0.5,1\n1.5,0,1,3\n").unwrap();
    let CaseData::Profiles(p) = f.data else {
        panic!()
    };
    assert_eq!(p.len(), 2);
    assert_eq!(p[0].time, 0.5);
    assert_eq!(p[0].stress, vec![1.0, 2.0]);
    assert_eq!(p[0].lines, vec![3, 2], "lines follow the sorted rows");
    assert_eq!(
        p[1].positions,
        Positions::Elements {
            left: vec![0.0],
            right: vec![1.0]
        }
    );
}

#[test]
fn bad_cells_and_geometry_name_line_and_column() {
    let e = read("t,x_left,x_right,stress\n0.5,0,0.5,abc\n").unwrap_err();
    assert_eq!((e.line, e.column, e.key.as_str()), (2, 4, "stress"), "{e}");
    let e = read("t,x_left,x_right,stress\n0.5,0,0.5,inf\n").unwrap_err();
    assert!(e.message.contains("not finite"), "{e}");
    let e = read("t,x_left,x_right,stress\n0.5,0,0.5,1\n0.4,0,0.5,1\n").unwrap_err();
    assert_eq!((e.line, e.key.as_str()), (3, "t"), "{e}");
    let e = read("t,x_left,x_right,stress\n0.5,0,0.6,1\n0.5,0.5,1,1\n").unwrap_err();
    assert!(e.message.contains("overlaps itself"), "{e}");
    let e = read("t,x_left,x_right,stress\n0.5,0,0.4,1\n0.5,0.5,1,1\n").unwrap_err();
    assert!(e.message.contains("does not cover the bar"), "{e}");
    let e = read("t,x,stress\n0.5,0.2,1\n0.5,0.2,1\n").unwrap_err();
    assert!(e.message.contains("overlap"), "{e}");
    let e = read("t,x,stress\n0.5,0.2\n").unwrap_err();
    assert_eq!(e.line, 2, "{e}");
    let e = read("t,x,stress\n").unwrap_err();
    assert!(e.message.contains("no rows"), "{e}");
    let e = read("t,force\n0,1\n0,2\n").unwrap_err();
    assert_eq!((e.line, e.key.as_str()), (3, "t"), "{e}");
    let e = read("mode,omega\n1.5,2\n").unwrap_err();
    assert_eq!((e.line, e.key.as_str()), (2, "mode"), "{e}");
}

#[test]
fn queries_need_only_the_keys() {
    let q = read_case("q.csv", "q", "t,x\n0.5,0.1\n0.5,0.2\n", Want::Query).unwrap();
    let CaseData::Profiles(p) = q.data else {
        panic!()
    };
    assert!(p[0].stress.is_empty());
    let q = read_case("q.csv", "q", "t\n0\n1\n", Want::Query).unwrap();
    assert!(matches!(q.data, CaseData::Force(_)));
}
