//! The explanation panel: what the IK branches, the Jacobian, manipulability and the
//! singularities mean (a teacher's words), the three recipes this page covers as the BSV page
//! states them (input, output, prerequisites, steps, expected result), and the safety line.
//! All text is Fluent (`ik2r-ex-*`, `ik2r-rc-*`); this file only arranges it.

/// The concept sections: (title id, paragraph ids).
const CONCEPTS: [(&str, &[&str]); 5] = [
    (
        "ik2r-ex-branches-title",
        &["ik2r-ex-branches", "ik2r-ex-branches-2"],
    ),
    ("ik2r-ex-jacobian-title", &["ik2r-ex-jacobian"]),
    ("ik2r-ex-w-title", &["ik2r-ex-w", "ik2r-ex-ellipse"]),
    ("ik2r-ex-sing-title", &["ik2r-ex-sing"]),
    ("ik2r-ex-flat-title", &["ik2r-ex-flat"]),
];

/// A recipe card: id prefix (`ik2r-rc-<p>-…`) and the number of steps.
const RECIPES: [(&str, usize); 3] = [("ik", 3), ("jac", 3), ("manip", 3)];

/// The panel's markup.
pub fn markup() -> String {
    let mut html = String::from(
        "<section class=\"ik2r-explain\" data-testid=\"ik-2r-explain\" data-section=\"explain\">\
         <h2 data-i18n=\"ik2r-explain-title\"></h2><div class=\"ik2r-concepts\">",
    );
    for (title, paragraphs) in CONCEPTS {
        html.push_str(&format!("<article><h3 data-i18n=\"{title}\"></h3>"));
        for p in paragraphs {
            html.push_str(&format!("<p data-i18n=\"{p}\"></p>"));
        }
        html.push_str("</article>");
    }
    html.push_str(
        "</div><h2 data-i18n=\"ik2r-recipes-title\"></h2>\
         <p class=\"ik2r-hint\" data-i18n=\"ik2r-recipes-hint\"></p><div class=\"ik2r-recipes\">",
    );
    for (p, steps) in RECIPES {
        html.push_str(&format!(
            "<article class=\"ik2r-recipe\"><h3 data-i18n=\"ik2r-rc-{p}-title\"></h3>\
             <p data-i18n=\"ik2r-rc-{p}-summary\"></p><dl>\
             <dt data-i18n=\"ik2r-rc-input\"></dt><dd data-i18n=\"ik2r-rc-{p}-input\"></dd>\
             <dt data-i18n=\"ik2r-rc-output\"></dt><dd data-i18n=\"ik2r-rc-{p}-output\"></dd>\
             <dt data-i18n=\"ik2r-rc-prereq\"></dt><dd data-i18n=\"ik2r-rc-{p}-prereq\"></dd>\
             <dt data-i18n=\"ik2r-rc-steps\"></dt><dd><ol>"
        ));
        for s in 1..=steps {
            html.push_str(&format!("<li data-i18n=\"ik2r-rc-{p}-step{s}\"></li>"));
        }
        html.push_str(&format!(
            "</ol></dd><dt data-i18n=\"ik2r-rc-expected\"></dt>\
             <dd data-i18n=\"ik2r-rc-{p}-expected\"></dd></dl>\
             <p class=\"ik2r-hint\" data-i18n=\"ik2r-rc-{p}-note\"></p></article>"
        ));
    }
    html.push_str(
        "</div><p class=\"ik2r-safety\" data-testid=\"ik-2r-safety\" data-i18n=\"ik2r-safety\"></p>\
         </section>",
    );
    html
}
