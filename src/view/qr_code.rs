//! The QR code of a link, as the one SVG path "Share" draws: the modules from `qrcodegen`, a
//! quiet zone of [`QUIET_ZONE`] modules on every side, one unit per module.
//!
//! The code is the smallest version that holds the link at error correction level L, with the
//! level raised as far as that version allows (fewer, larger modules read best from the back
//! of a room). A link longer than a version 40 code holds (2,953 bytes at level L) has no code.

use qrcodegen::{QrCode, QrCodeEcc};

/// The light margin around the code, in modules (the standard's minimum).
pub const QUIET_ZONE: usize = 4;

/// A QR code as SVG path data.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct QrPicture {
    /// Modules across the code (21 for version 1 up to 177 for version 40).
    pub modules: usize,
    /// The SVG's side in modules: the code and its quiet zone on both sides.
    pub side: usize,
    /// The dark modules as path data, one closed rectangle per run of dark modules in a row,
    /// in units of modules, the quiet zone included (`M4,4h7v1h-7z...`).
    pub dark_path: String,
}

/// The QR code of `text`; `None` when no QR code holds it.
pub fn qr_picture(text: &str) -> Option<QrPicture> {
    let code = QrCode::encode_text(text, QrCodeEcc::Low).ok()?;
    let modules = usize::try_from(code.size()).ok()?;
    let dark = |x: usize, y: usize| code.get_module(x as i32, y as i32);
    Some(QrPicture {
        modules,
        side: modules + 2 * QUIET_ZONE,
        dark_path: runs_path(modules, dark),
    })
}

/// Path data of the dark runs of a `modules`-square grid, offset by the quiet zone.
fn runs_path(modules: usize, dark: impl Fn(usize, usize) -> bool) -> String {
    let mut path = String::new();
    for y in 0..modules {
        let mut x = 0;
        while x < modules {
            if !dark(x, y) {
                x += 1;
                continue;
            }
            let start = x;
            while x < modules && dark(x, y) {
                x += 1;
            }
            let run = x - start;
            path.push_str(&format!(
                "M{},{}h{run}v1h-{run}z",
                start + QUIET_ZONE,
                y + QUIET_ZONE
            ));
        }
    }
    path
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid of dark modules (quiet zone included) that `path` paints.
    fn painted(picture: &QrPicture) -> Vec<Vec<bool>> {
        let mut grid = vec![vec![false; picture.side]; picture.side];
        for rect in picture.dark_path.split('z').filter(|r| !r.is_empty()) {
            let rest = rect.strip_prefix('M').expect("a rectangle starts with M");
            let (xy, rest) = rest.split_once('h').expect("then a run");
            let (x, y) = xy.split_once(',').expect("x,y");
            let (run, tail) = rest.split_once('v').expect("then one row down");
            assert_eq!(tail, format!("1h-{run}"));
            let (x, y, run): (usize, usize, usize) =
                (x.parse().unwrap(), y.parse().unwrap(), run.parse().unwrap());
            for cell in &mut grid[y][x..x + run] {
                assert!(!*cell, "runs do not overlap");
                *cell = true;
            }
        }
        grid
    }

    #[test]
    fn the_path_paints_exactly_the_dark_modules_inside_the_quiet_zone() {
        let link = "https://example.org/bsv/#/ik-2r?l1=1.2&l2=0.8&x=0.9&y=0.6&lang=ja";
        let picture = qr_picture(link).expect("a short link has a code");
        let code = QrCode::encode_text(link, QrCodeEcc::Low).unwrap();
        assert_eq!(picture.modules, code.size() as usize);
        assert_eq!(picture.side, picture.modules + 8);
        let grid = painted(&picture);
        for (y, row) in grid.iter().enumerate() {
            for (x, &dark) in row.iter().enumerate() {
                let inside = (QUIET_ZONE..QUIET_ZONE + picture.modules).contains(&x)
                    && (QUIET_ZONE..QUIET_ZONE + picture.modules).contains(&y);
                let expected =
                    inside && code.get_module((x - QUIET_ZONE) as i32, (y - QUIET_ZONE) as i32);
                assert_eq!(dark, expected, "module ({x}, {y})");
            }
        }
    }

    #[test]
    fn a_short_link_makes_a_small_code_with_raised_error_correction() {
        let picture = qr_picture("http://127.0.0.1:8080/#/pendulum-energy").unwrap();
        // Version 3 (29 modules) holds 40 bytes at level M and above.
        assert!(picture.modules <= 29, "{} modules", picture.modules);
        let code =
            QrCode::encode_text("http://127.0.0.1:8080/#/pendulum-energy", QrCodeEcc::Low).unwrap();
        assert_ne!(code.error_correction_level(), QrCodeEcc::Low);
    }

    #[test]
    fn the_longest_link_a_code_holds_and_one_byte_more() {
        let longest = format!("https://a.example/#/lesson?l={}", "x".repeat(2953 - 29));
        assert_eq!(longest.len(), 2953);
        assert_eq!(qr_picture(&longest).map(|p| p.modules), Some(177));
        assert_eq!(qr_picture(&format!("{longest}x")), None);
    }
}
