"""The report scripts' code (reports/README.md "The package"): reading and checking reports and
journals, grouping a report for its outputs, the pictures, summary.md, the HTML page and the
papers' claims. reports/plot.py, plot_paths.py, html_report.py and check_claims.py are its
command lines; run as scripts, they find this package beside them with no path set.
"""
