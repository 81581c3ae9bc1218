# Step tests (#13): the plan (pure) and the runner against the built-in simulator. Included
# from tests/tuning/CMakeLists.txt.
lk_add_test(tst_steptestplan SOURCES tst_steptestplan.cpp LIBS lkcore lktext)
lk_add_test(tst_steptestrunner SOURCES tst_steptestrunner.cpp LIBS lkcore TIMEOUT 240)
