//! "Copy as Python": a short pandas + matplotlib snippet that loads the CSV the page exports
//! and draws the plot tab on screen (the same series, the same log scale).

/// The snippet for the CSV file `csv_name` and the tab titled `title` drawing `columns`
/// (their CSV headers) against `t_s [s]`, on a log10 y axis when `log`.
pub fn snippet(csv_name: &str, title: &str, columns: &[String], log: bool) -> String {
    let quoted: Vec<String> = columns.iter().map(|c| py_string(c)).collect();
    format!(
        "import pandas as pd\nimport matplotlib.pyplot as plt\n\n\
         # The file the page's \"Export CSV\" button saves (every sample since t = 0).\n\
         df = pd.read_csv({file})\n\
         columns = [{cols}]\n\
         ax = df.plot(x=\"t_s [s]\", y=columns, title={title}{logy})\n\
         ax.set_xlabel(\"t [s]\")\n\
         plt.show()\n",
        file = py_string(csv_name),
        cols = quoted.join(", "),
        title = py_string(title),
        logy = if log { ", logy=True" } else { "" },
    )
}

/// A Python string literal.
fn py_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_snippet_loads_the_file_and_plots_the_columns() {
        let s = snippet(
            "attlab-p4-seed1.csv",
            "Roll error \"of\" each filter",
            &[
                "kf.angle_err_deg [deg]".into(),
                "cf.angle_err_deg [deg]".into(),
            ],
            true,
        );
        assert!(s.contains("pd.read_csv(\"attlab-p4-seed1.csv\")"), "{s}");
        assert!(
            s.contains("columns = [\"kf.angle_err_deg [deg]\", \"cf.angle_err_deg [deg]\"]"),
            "{s}"
        );
        assert!(
            s.contains("title=\"Roll error \\\"of\\\" each filter\", logy=True"),
            "{s}"
        );
    }
}
