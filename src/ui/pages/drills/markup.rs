//! The page's HTML skeleton (its stylesheet, `style.css` beside this file, is bundled into
//! `www/app.css` by `scripts/build-dist.sh`). Every fixed word is a `data-i18n` id filled by
//! the shell (and `dom::relocalize`) from `locales/*/drills.ftl` and `recipes.ftl`; elements
//! the code drives carry `data-drills="<role>"`, and the ones tests drive carry `data-testid`,
//! `data-field`, `data-download`, `data-cmd` and `data-copy`.

use crate::recipes::INFOS;
use crate::ui::kit::form::escape;
use crate::ui::kit::{exports, readouts};

/// The class and test-id prefix of the page's kit widgets.
pub(super) const PREFIX: &str = "drills";

fn recipe_options() -> String {
    let mut html = String::new();
    for recipe in INFOS {
        let id = escape(recipe.id);
        html.push_str(&format!(
            "<option value=\"{id}\" data-i18n=\"recipe-{id}-title\"></option>"
        ));
    }
    html
}

/// The whole page; the form, the explanation and the result are filled by the code.
pub fn page() -> String {
    format!(
        "<div class=\"drills\" data-testid=\"drills-page\" data-state=\"idle\">\
<header class=\"drills-head\"><h1 data-i18n=\"drills-title\"></h1>\
<p class=\"drills-lede\" data-i18n=\"drills-lede\"></p>\
<p class=\"drills-notice\" data-drills=\"url-notice\" data-testid=\"drills-url-notice\" role=\"status\" hidden></p></header>\
<div class=\"drills-layout\">\
<section class=\"drills-card drills-setup\" data-section=\"form\" aria-labelledby=\"drills-recipe-title\">\
<div class=\"drills-picker\"><label for=\"drills-recipe\" data-i18n=\"drills-picker-label\"></label>\
<select id=\"drills-recipe\" data-drills=\"recipe\" data-testid=\"drills-recipe\">{options}</select></div>\
<h2 id=\"drills-recipe-title\" data-drills=\"recipe-title\"></h2>\
<p class=\"drills-blurb\" data-drills=\"recipe-blurb\"></p>\
<form class=\"drills-form\" data-drills=\"form\" novalidate></form>\
<div class=\"drills-actions\">\
<button type=\"button\" class=\"button primary drills-run\" data-drills=\"run\" data-testid=\"drills-run\" data-i18n=\"drills-run\"></button>\
<button type=\"button\" class=\"button\" data-drills=\"reset\" data-testid=\"drills-reset\" data-i18n=\"drills-reset\"></button></div>\
<p class=\"drills-status\" data-drills=\"status\" data-testid=\"drills-status\" role=\"status\" aria-live=\"polite\"></p>\
<p class=\"drills-error drills-general-error\" data-drills=\"error\" data-testid=\"drills-error\" role=\"alert\" hidden></p>\
</section>\
<section class=\"drills-card drills-output\" data-section=\"result\" data-drills=\"output\" data-testid=\"drills-output\" data-run=\"0\" \
aria-labelledby=\"drills-output-title\">\
<h2 id=\"drills-output-title\" data-i18n=\"drills-output-title\"></h2>\
<p class=\"drills-stale\" data-drills=\"stale\" data-testid=\"drills-stale\" role=\"status\" data-i18n=\"drills-stale\" hidden></p>\
<p class=\"drills-hint\" data-drills=\"empty\" data-i18n=\"drills-output-empty\"></p>\
<div class=\"drills-result\" data-drills=\"result\" hidden>\
<h3 class=\"drills-sub\" data-i18n=\"drills-summary-label\"></h3>\
<pre class=\"drills-summary\" data-drills=\"summary\" data-testid=\"drills-summary\"></pre>\
<div class=\"drills-warnings\" data-drills=\"warnings\" data-testid=\"drills-warnings\" role=\"status\" hidden></div>\
<div class=\"drills-table-options\"><label class=\"drills-exact\"><input type=\"checkbox\" data-exact data-testid=\"drills-exact\"> \
<span data-i18n=\"drills-table-exact\"></span></label>\
<p class=\"drills-hint\" data-drills=\"rounded-note\" data-i18n=\"drills-table-rounded\"></p></div>\
<div class=\"drills-files\" data-drills=\"files\"></div>\
{exports}</div></section>\
<section class=\"drills-card drills-about\" data-section=\"explain\" data-testid=\"drills-about\" aria-labelledby=\"drills-about-title\">\
<h2 id=\"drills-about-title\" data-i18n=\"drills-about-title\"></h2>\
<p data-drills=\"about\"></p>\
<div class=\"drills-quirks\"><h3 data-i18n=\"drills-quirks-title\"></h3>\
<p data-drills=\"quirk\" data-testid=\"drills-quirks\"></p></div>\
<p class=\"drills-hint\" data-i18n=\"drills-about-parity\"></p>\
</section>\
</div>{live}</div>",
        options = recipe_options(),
        exports = exports::markup(PREFIX),
        live = readouts::live_markup(PREFIX),
    )
}
