use intl_memoizer::Memoizable;
use intl_pluralrules::{PluralRuleType, PluralRules as IntlPluralRules};
use unic_langid::subtags::Language;
use unic_langid::LanguageIdentifier;

pub struct PluralRules(pub IntlPluralRules);

impl Memoizable for PluralRules {
    type Args = (PluralRuleType,);
    type Error = &'static str;
    fn construct(lang: LanguageIdentifier, args: Self::Args) -> Result<Self, Self::Error> {
        // The rules of the bundle's language when the rules hold it, else English's: what
        // fluent_langneg's lookup gave for the rules' locales (BSV Playground's copy: English
        // and Japanese, each a bare language), without parsing a language tag.
        let available = IntlPluralRules::get_locales(args.0);
        let language = if available.iter().any(|l| l.language == lang.language) {
            lang.language
        } else {
            Language::from_bytes(b"en").map_err(|_| "no English plural rules")?
        };
        let pr_lang = LanguageIdentifier::from_raw_parts_unchecked(language, None, None, None);
        Ok(Self(IntlPluralRules::create(pr_lang, args.0)?))
    }
}
