# Nomoto model, identification, encounter assessment, helm search, policy, `fairway helm`.
fw_test(test_nomoto test_nomoto.c)
