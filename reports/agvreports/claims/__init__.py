"""The papers' claims (reports/claims.json) checked against sweep reports: reports/check_claims.py."""
