# Command-line behaviour: help, exit codes, one-line errors.
fw_cli_test(cli_help 0 "usage: fairway COMMAND" --help)
fw_cli_test(cli_unknown_command 2 "unknown command" frobnicate)
fw_cli_test(cli_ship_c3 0 "ship c3" ship c3)
fw_cli_test(cli_ship_unknown 2 "unknown ship 'nosuch'" ship nosuch)

# Standard manoeuvres and the calibration.
set(FW_C3_TURN manoeuvre turning --ship c3 --speed 26.7 --rudder 35 --side starboard)
fw_cli_test(cli_turning 0 "tactical diameter +1[34][0-9][0-9]\\.[0-9] m" ${FW_C3_TURN})
fw_cli_test(cli_turning_json 0 "^\\{\"ship\": \"c3\".*\"advance_m\": 1[01][0-9][0-9]\\.[0-9]+.*\"imo_advance_ok\": true" ${FW_C3_TURN} --json)
fw_cli_test(cli_turning_port 0 "35 deg port at 27.16 kn" manoeuvre turning --ship c3 --speed 27.16 --rudder 35 --side port)
fw_cli_test(cli_zigzag_10 0 "first overshoot .*pass" manoeuvre zigzag --ship c3 --speed 26.7 --angle 10)
fw_cli_test(cli_zigzag_20_json 0 "\"angle_deg\": 20.00.*\"imo_ok1\": true" manoeuvre zigzag --ship c3 --speed 26.7 --angle 20 --json)
fw_script_test(cli_turning_csv 0 "^t_s,east_m,north_m,heading_deg,u_mps,v_mps,r_degps,rudder_deg,helm_deg,propeller_rps"
               turning_csv.sh)
fw_cli_test(cli_report 0 "all criteria met" manoeuvre report --ship c3)
# c3-paper's trial file has equation-10 rows: a table of them, not IMO turning circles
fw_cli_test(cli_report_eq10 0 "^ +14.55 +5 +[0-9]+/[0-9]+ .* 0.1[0-9][0-9]/0.170" manoeuvre report --ship c3-paper)
fw_cli_test(cli_report_eq10_imo 0 "all criteria met" manoeuvre report --ship c3-paper)
fw_cli_test(cli_manoeuvre_help 0 "usage: fairway manoeuvre" manoeuvre --help)
fw_cli_test(cli_calibrate_help 0 "usage: fairway calibrate" calibrate --help)

# Bad input: one line naming what is wrong, exit code 2.
fw_cli_test(cli_bad_unknown_ship 2 "unknown ship 'nosuch'" manoeuvre turning --ship nosuch --speed 10 --rudder 35)
fw_cli_test(cli_bad_broken_ship 2 "broken_ship.yaml:[0-9]+: YAML syntax error"
            manoeuvre turning --ship ${CMAKE_CURRENT_SOURCE_DIR}/data/broken_ship.yaml --speed 10 --rudder 35)
fw_cli_test(cli_bad_nan_coefficient 2 "nan_coef_ship.yaml:[0-9]+: hull.N_r: 'nan' is not a finite number"
            manoeuvre turning --ship ${CMAKE_CURRENT_SOURCE_DIR}/data/nan_coef_ship.yaml --speed 2 --rudder 35)
fw_cli_test(cli_bad_unknown_field 2 "unknown_field_ship.yaml:[0-9]+: particulars.depth: unknown field"
            ship ${CMAKE_CURRENT_SOURCE_DIR}/data/unknown_field_ship.yaml)
fw_cli_test(cli_bad_negative_speed 2 "--speed: must be positive" ${FW_C3_TURN} --speed -5)
fw_cli_test(cli_bad_speed_text 2 "--speed: 'fast' is not a number" manoeuvre turning --ship c3 --speed fast --rudder 35)
fw_cli_test(cli_bad_speed_nan 2 "--speed: 'nan' is not a finite number" manoeuvre turning --ship c3 --speed nan --rudder 35)
fw_cli_test(cli_bad_rudder_beyond_max 2 "--rudder: 40 deg is beyond c3's maximum of 35 deg"
            manoeuvre turning --ship c3 --speed 26.7 --rudder 40)
fw_cli_test(cli_bad_side 2 "--side: 'left' is not starboard or port" ${FW_C3_TURN} --side left)
fw_cli_test(cli_bad_kind 2 "'spiral' is not turning, zigzag or report" manoeuvre spiral --ship c3)
fw_cli_test(cli_bad_missing_rudder 2 "needs --speed and --rudder" manoeuvre turning --ship c3 --speed 26.7)
fw_cli_test(cli_bad_option 2 "unknown option '--rpm'" manoeuvre turning --ship c3 --rpm 80)
fw_cli_test(cli_bad_trial 2 "c3-trial-bad.yaml:[0-9]+: turns\\[0\\].side: 'left' is not starboard or port"
            calibrate --ship c3 --trial ${CMAKE_CURRENT_SOURCE_DIR}/data/c3-trial-bad.yaml)
fw_cli_test(cli_bad_trial_rudder 2 "c3-trial-rudder.yaml:10: nomoto_targets.rudders_deg: 40 deg is beyond c3's maximum rudder of 35 deg"
            calibrate --ship c3 --trial ${CMAKE_CURRENT_SOURCE_DIR}/data/c3-trial-rudder.yaml)
fw_cli_test(cli_trial_out_of_reach 0 "c3-trial-reach.yaml:6: trial rate deg/s 3.000 at 26.70 kn, 35 deg stbd is out of reach of the fit"
            calibrate --ship c3 --trial ${CMAKE_CURRENT_SOURCE_DIR}/data/c3-trial-reach.yaml)
# c3-paper as its file has it against the sea trial and equations 9-10: every target reported
fw_cli_test(cli_calibrate_check 0 "eq +stbd +26.70 +35.0 eq-9 hist +eq 9 " calibrate --ship c3-paper --check)

# The plotting script turns manoeuvre CSVs into PNG sheets (Debian's python3).
fw_script_test(analysis_plot_manoeuvre 0 "turning_starboard_26.70kn.png [0-9]{5,} bytes" plot_manoeuvre.sh)
fw_script_test(analysis_plot_bad_csv 2 "plot_manoeuvre: .*bad.csv: missing columns" plot_bad_csv.sh)
