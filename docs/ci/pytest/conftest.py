# pytest's hook for the screenshot tests beside it (docs/ci.md, "pytest"): `pytest --update` rewrites the
# references of the screenshots that differ (or are missing) from this run's images.
def pytest_addoption(parser):
    parser.addoption("--update", action="store_true",
                     help="write the references of failing screenshot tests from this run (then look at them)")
