//! `odd-pages <docs dir> <stylesheet> <out dir>`: writes `<out>/<name>.html` for
//! every `<docs>/odd-<name>.md` (the ODD descriptions of Shoal's models) and copies
//! the stylesheet to `<out>/odd.css`. The markdown stays the one source; the pages
//! are made at build time by the Trunk hook `web/odd-pages.sh`.
//!
//! Links to another ODD become links to its page; links to the other docs, which
//! are not published with the app, become plain text naming the file's path in
//! the repository, so a page never has a dead link. The pages carry no script and
//! no inline style (the app's Content Security Policy allows neither).

use std::fs;
use std::path::{Path, PathBuf};

use pulldown_cmark::{html, CowStr, Event, Options, Parser, Tag, TagEnd};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [docs, css, out] = args.as_slice() else {
        eprintln!("usage: odd-pages <docs dir> <stylesheet> <out dir>");
        std::process::exit(2);
    };
    if let Err(e) = run(Path::new(docs), Path::new(css), Path::new(out)) {
        eprintln!("odd-pages: {e}");
        std::process::exit(1);
    }
}

fn run(docs: &Path, css: &Path, out: &Path) -> std::io::Result<()> {
    fs::create_dir_all(out)?;
    fs::copy(css, out.join("odd.css"))?;
    let mut sources: Vec<PathBuf> = fs::read_dir(docs)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| page_name(p).is_some())
        .collect();
    sources.sort();
    if sources.is_empty() {
        return Err(std::io::Error::other("no docs/odd-*.md found"));
    }
    for source in sources {
        let name = page_name(&source).expect("filtered above");
        let markdown = fs::read_to_string(&source)?;
        let page = render(&markdown, &format!("docs/odd-{name}.md"));
        fs::write(out.join(format!("{name}.html")), page)?;
    }
    Ok(())
}

/// `odd-reef.md` -> `reef`.
fn page_name(path: &Path) -> Option<String> {
    let file = path.file_name()?.to_str()?;
    let name = file.strip_prefix("odd-")?.strip_suffix(".md")?;
    (!name.is_empty()).then(|| name.to_string())
}

/// Where a link of an ODD points once published: another ODD's page, an outside
/// address unchanged, or nothing (a doc that is not published).
fn published(dest: &str) -> Option<String> {
    if dest.contains("://") || dest.starts_with("mailto:") {
        return Some(dest.to_string());
    }
    let (file, anchor) = match dest.split_once('#') {
        Some((f, a)) => (f, Some(a)),
        None => (dest, None),
    };
    if file.is_empty() {
        return Some(dest.to_string());
    }
    let name = page_name(Path::new(file))?;
    Some(match anchor {
        Some(a) => format!("{name}.html#{a}"),
        None => format!("{name}.html"),
    })
}

/// The whole page for one ODD's markdown.
fn render(markdown: &str, source: &str) -> String {
    let options = Options::ENABLE_TABLES | Options::ENABLE_HEADING_ATTRIBUTES;
    let mut title = String::new();
    let mut in_title = false;
    // The unpublished doc the current link names (its path in the repository,
    // with the anchor) and the events of the link's text.
    let mut unpublished: Option<(String, String, Vec<Event>)> = None;
    let mut events = Vec::new();
    for event in Parser::new_ext(markdown, options) {
        if let Some((path, anchor, inner)) = unpublished.as_mut() {
            if matches!(event, Event::End(TagEnd::Link)) {
                let text: String = inner
                    .iter()
                    .filter_map(|e| match e {
                        Event::Text(t) | Event::Code(t) => Some(t.as_ref()),
                        _ => None,
                    })
                    .collect();
                let file = path.trim_start_matches("docs/");
                let full = if anchor.is_empty() {
                    path.clone()
                } else {
                    format!("{path}#{anchor}")
                };
                let code = format!("<code class=\"repo-path\">{}</code>", escape(&full));
                if text == file || text == *path || text == *anchor {
                    // The link's words only name the place: name it in full.
                    events.push(Event::Html(CowStr::from(code)));
                } else {
                    events.append(inner);
                    events.push(Event::Html(CowStr::from(format!(
                        " <span class=\"repo-path\">(in the repository: {code})</span>"
                    ))));
                }
                unpublished = None;
            } else {
                inner.push(event);
            }
            continue;
        }
        match event {
            Event::Start(Tag::Heading { level, .. }) if title.is_empty() => {
                in_title = level == pulldown_cmark::HeadingLevel::H1;
                events.push(event);
            }
            Event::Text(ref t) if in_title => {
                title.push_str(t);
                events.push(event);
            }
            Event::End(TagEnd::Heading(_)) => {
                in_title = false;
                events.push(event);
            }
            Event::Start(Tag::Link {
                link_type,
                dest_url,
                title: link_title,
                id,
            }) => match published(&dest_url) {
                Some(to) => events.push(Event::Start(Tag::Link {
                    link_type,
                    dest_url: CowStr::from(to),
                    title: link_title,
                    id,
                })),
                None => {
                    let (file, anchor) = dest_url.split_once('#').unwrap_or((&dest_url, ""));
                    unpublished = Some((format!("docs/{file}"), anchor.to_string(), Vec::new()));
                }
            },
            other => events.push(other),
        }
    }
    let mut body = String::new();
    html::push_html(&mut body, events.into_iter());
    let title = if title.is_empty() { "ODD" } else { &title };
    format!(
        "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title} · Shoal</title>\n<link rel=\"stylesheet\" href=\"odd.css\">\n</head>\n\
         <body>\n<main>\n{body}</main>\n<footer>Shoal · made from <code>{source}</code> \
         in the repository</footer>\n</body>\n</html>\n",
        title = escape(title),
        source = escape(source),
    )
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_to_other_odds_stay_links_and_unpublished_docs_become_paths() {
        let page = render(
            "# T\n\nSee [reef](odd-reef.md#2-entities), [boids.md](boids.md), \
             [the rows](departures.md#a), [b](departures.md#b) and [JASSS](https://www.jasss.org/).\n",
            "docs/odd-x.md",
        );
        assert!(
            page.contains("<a href=\"reef.html#2-entities\">reef</a>"),
            "{page}"
        );
        assert!(
            !page.contains(".md\""),
            "a link to an unpublished doc: {page}"
        );
        assert!(page.contains("See <a href=\"reef.html#2-entities\">reef</a>, <code class=\"repo-path\">docs/boids.md</code>, "), "{page}");
        assert!(
            page.contains("the rows <span class=\"repo-path\">(in the repository: <code class=\"repo-path\">docs/departures.md#a</code>)</span>"),
            "{page}"
        );
        assert!(
            page.contains("<code class=\"repo-path\">docs/departures.md#b</code> and"),
            "{page}"
        );
        assert!(
            page.contains("<a href=\"https://www.jasss.org/\">JASSS</a>"),
            "{page}"
        );
        assert!(page.contains("<title>T · Shoal</title>"), "{page}");
        assert!(
            !page.contains("<script") && !page.contains("style="),
            "{page}"
        );
    }
}
