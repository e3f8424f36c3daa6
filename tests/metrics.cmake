tl_add_test(test_metrics SOURCES test_metrics.c)
