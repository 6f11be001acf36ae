# Nomoto model, identification, encounter assessment, helm search, policy, `fairway helm`.
fw_test(test_nomoto test_nomoto.c)
fw_test(test_avoid test_avoid.c)
fw_test(test_avoid_rules test_avoid_rules.c)
target_link_libraries(test_avoid_rules PRIVATE fairway_run)
fw_test(test_identify test_identify.c)

# The paper's cases at its action times (own ship C-3 at 10 kn heading north
# from (0,0), targets propagated straight): head-on t = 15 s (paper 20 deg),
# crossing t = 163 s (17 deg), complex crossing t = 105 s (15 deg); within 3 deg.
fw_cli_test(helm_paper_head_on 0 "required: starboard (1[7-9]|2[0-3]) deg"
            helm --ship c3 --own 0,77.17,0,10 --target 0,1922.83,180,10)
fw_cli_test(helm_paper_crossing 0 "required: starboard (1[4-9]|20) deg"
            helm --ship c3 --own 0,838.5,0,10 --target 1161.5,2000,270,10)
fw_cli_test(helm_paper_complex_crossing 0 "required: starboard (1[2-8]) deg"
            helm --ship c3 --own 0,540.2,0,10 --target 0,2567.9,180,8 --target 1567.9,2000,270,8)
fw_cli_test(helm_json 0 "\"side\": \"starboard\", \"helm_deg\": [0-9]+"
            helm --ship c3 --own 0,0,0,10 --target 0,1800,180,10 --json)
fw_cli_test(helm_clear 0 "no target enters the domain"
            helm --ship c3 --own 0,0,0,10 --target 3000,0,0,10)
fw_cli_test(helm_help 0 "usage: fairway helm" helm --help)
fw_cli_test(helm_bad_number 2 "--own: '0,x,0,10' is not a number|--own: 'x' is not a number"
            helm --ship c3 --own 0,x,0,10)
fw_cli_test(helm_nan 2 "not a finite number" helm --ship c3 --own 0,0,0,10 --target 0,nan,180,10)
fw_cli_test(helm_negative_speed 2 "speed -3 kn is negative" helm --ship c3 --own 0,0,0,10 --target 0,900,180,-3)
fw_cli_test(helm_unknown_ship 2 "unknown ship 'nosuch'" helm --ship nosuch --own 0,0,0,10)
fw_cli_test(helm_missing_own 2 "--own is required" helm --ship c3 --target 0,900,180,10)
fw_cli_test(helm_short_target 2 "expected E,N,COURSE,SPEED" helm --ship c3 --own 0,0,0,10 --target 0,900,180)
fw_cli_test(helm_bad_domain 2 "--domain: must be positive" helm --ship c3 --own 0,0,0,10 --domain -5)
fw_cli_test(identify_small_grid 0 "^wrote .*c3-identified-test.yaml"
            identify --ship c3 --speeds 14.55,20.12,26.7 --rudders 10,20,35 --sides starboard --duration 600
            --out ${CMAKE_CURRENT_BINARY_DIR}/c3-identified-test.yaml --force)
# --sides both: a regression and slip fit per side, written as nomoto: and nomoto_port:
fw_cli_test(identify_both_sides 0 "^port: drift [0-9.]+ rad per unit"
            identify --ship c3 --speeds 14.55,20.12,26.7 --rudders 10,20,35 --sides both --duration 600
            --out ${CMAKE_CURRENT_BINARY_DIR}/c3-identified-both.yaml --force)
# c3-mmg's knowledge base is reproduced by the command in its header (about 1 s)
fw_script_test(identify_c3mmg 0 "ok: c3-mmg's knowledge base is its command's" identify_c3mmg.sh)
fw_cli_test(identify_bad_slip_from 2 "unknown ship 'nosuch'"
            identify --ship c3 --slip-from nosuch --out ${CMAKE_CURRENT_BINARY_DIR}/c3-slip.yaml)
fw_cli_test(identify_slip_from_no_kb 2 "--slip-from: ship 'kvlcc2' has no knowledge base"
            identify --ship c3 --slip-from kvlcc2 --out ${CMAKE_CURRENT_BINARY_DIR}/c3-slip.yaml)
fw_cli_test(identify_bad_speed 2 "--speeds: 'x' is not a number" identify --ship c3 --speeds 10,x)
fw_cli_test(identify_unknown_ship 2 "unknown ship 'nosuch'" identify --ship nosuch)
fw_cli_test(identify_bad_rudder 2 "--rudders: 50 deg outside" identify --ship c3 --rudders 10,50)

# The helm search before the decision was made cheaper: the reference that
# test_decide and bench_helm compare fw_helm_search with.
add_library(fw_helm_reference STATIC helm_reference.c)
target_link_libraries(fw_helm_reference PUBLIC fairway_core)
target_include_directories(fw_helm_reference PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
fw_test(test_decide test_decide.c decide_scenes.c)
target_link_libraries(test_decide PRIVATE fw_helm_reference)
fw_test(test_decide_parts test_decide_parts.c decide_scenes.c)
# the environment (src/env) in the world, the dynamics and the helm search
fw_test(test_env test_env.c decide_scenes.c)
target_link_libraries(test_env PRIVATE fw_helm_reference)
fw_test(test_env_predict test_env_predict.c)

# The environment: section of a scenario (scenario/scn_env.h) and the manoeuvres' --current
fw_script_test(env_run 0 "ok: the current carries the own ship" env_run.sh)
set_tests_properties(env_run PROPERTIES ENVIRONMENT "${fw_lsan}")
foreach(bad "negative:27: environment.current.speed_kn: -2 is out of range \\[0, 10\\]"
            "both:27: environment.current.tidal: give a uniform current .* or a tidal stream, not both"
            "wind:28: environment.wind: .*Nomoto dynamics have no wind force"
            "period:27: environment.current.tidal.period_h: 0 is out of range \\[1, 48\\]"
            "gust:27: environment.wind.gust_intensity: 0.5 is out of range \\[0, 0.3\\]"
            "windneg:27: environment.wind.speed_kn: -5 is out of range \\[0, 100\\]"
            "windhigh:27: environment.wind.speed_kn: 150 is out of range \\[0, 100\\]"
            "currenthigh:27: environment.current.speed_kn: 12 is out of range \\[0, 10\\]"
            "late:15: traffic.watch.late: -0.2 is out of range \\[0, 1\\]"
            "background:26: sensing.background: expected true or false"
            "neap:27: environment.current.tidal.neap_rate_kn: 2 kn is above the spring rate"
            "sensemode:26: sensing.mode: 'sonar' is not a sensing mode \\(perfect, ais, radar or ais\\+radar\\)"
            "dropout:26: sensing.dropout: 1.5 is out of range \\[0, 1\\]"
            "visibility:26: environment.visibility_nm: 0: a visibility is more than 0"
            "visneg:26: environment.visibility_nm: -2: a visibility is more than 0"
            "lapse:15: traffic.watch.lapse: 1.5 is out of range \\[0, 1\\]"
            "detect:15: traffic.watch.detect_s: -5 is out of range \\[0, 3600\\]"
            "laterange:15: traffic.watch.late_range_nm: a late action .* needs the range"
            "ownwatch:15: traffic.watch.own_ship: 'robot': expected perfect or human"
            "mixunknown:15: traffic.mix.reckless: unknown field \\(expected one of: compliant, late, passive"
            "mixsum:15: traffic.mix: the shares sum to 0.7; compliant, late and passive must sum to 1"
            "mixover:15: traffic.mix: the shares sum to 1.2"
            "mixrange:15: traffic.mix.late_range_nm: late ships \\(late > 0\\) need the range")
  string(REGEX MATCH "^[a-z]+" name "${bad}")
  string(REGEX REPLACE "^[a-z]+" "" pattern "${bad}")
  fw_cli_test(cli_run_env_${name} 2 "bad-${name}.yaml${pattern}" run
              ${CMAKE_CURRENT_SOURCE_DIR}/data/env/bad-${name}.yaml --out ${CMAKE_CURRENT_BINARY_DIR}/cli-runs)
endforeach()
fw_cli_test(cli_manoeuvre_current 0 "drift 360 -> 720 deg  1251.3 m in 1216.2 s towards 090 deg \\(2.00 kn\\)"
            manoeuvre turning --ship c3 --speed 12 --rudder 35 --current 2,090)
fw_cli_test(cli_manoeuvre_bad_current 2 "--current: give KN,DEG" manoeuvre turning --ship c3
            --speed 12 --rudder 35 --current 12,090)
fw_cli_test(cli_manoeuvre_wind 0 "drift 360 -> 720 deg   374.1 m in 1224.0 s towards 089 deg" manoeuvre turning
            --ship c3 --speed 12 --rudder 35 --wind 20,270)
fw_cli_test(cli_manoeuvre_bad_wind 2 "--wind: give KN,DEG, the speed \\(0 to 100 kn\\)"
            manoeuvre zigzag --ship c3 --speed 12 --angle 10 --wind -5,270)
fw_cli_test(cli_manoeuvre_wind_no_windage 2 "no-windage.yaml has no windage: section"
            manoeuvre zigzag --ship ${CMAKE_CURRENT_SOURCE_DIR}/data/env/no-windage.yaml
            --speed 12 --angle 10 --wind 20,270)
# The own ship deciding on AIS reports and on radar tracks (sense/sensing.h)
fw_script_test(sensing_run 0 "ok: the own ship decides on AIS reports and on radar tracks"
               sensing_run.sh)
set_tests_properties(sensing_run PROPERTIES ENVIRONMENT "${fw_lsan}")
# Restricted visibility: the own ship under rule 19 (avoid/policy.h)
fw_script_test(visibility_run 0 "ok: rule 19 in restricted visibility" visibility_run.sh)
set_tests_properties(visibility_run PROPERTIES ENVIRONMENT "${fw_lsan}")
