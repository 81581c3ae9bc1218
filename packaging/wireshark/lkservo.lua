-- Wireshark dissector for LK-TECH servo drives on RS485 (protocol V2.3 and V2.35), as exported
-- by `lkctl export RECORDING --pcap OUT` (docs/RECORDING.md "The pcap encapsulation"): link
-- type USER0, each packet a 2-byte pseudo-header (wire direction, frame direction) and one
-- frame. Layouts and scales: docs/PROTOCOL.md sections 4 to 6.
--
-- Installed in Wireshark's global Lua plugin folder; without the package:
--   wireshark -X lua_script:lkservo.lua capture.pcap

local lk = Proto("lkservo", "LK servo RS485")

local wire_names = { [0] = "rx", [1] = "tx" }
local kind_names = { [0] = "request", [1] = "reply", [2] = "echo", [3] = "no frame",
                     [4] = "decode context" }
local series_names = { [0] = "unknown (MF)", [1] = "MS", [2] = "MF", [3] = "MG", [4] = "MH" }
local generation_names = { [0] = "v2.3", [1] = "v2.35" }

-- code -> { name, request LEN, reply LEN }; 0x12 replies 42 (V2.3) or 58 (V2.35) bytes.
local commands = {
    [0x12] = { "read_model", 0, 42 },
    [0x19] = { "write_zero_rom", 0, 0 },
    [0x30] = { "read_pid", 0, 6 },
    [0x31] = { "write_pid_ram", 6, 6 },
    [0x32] = { "write_pid_rom", 6, 6 },
    [0x33] = { "read_accel", 0, 4 },
    [0x34] = { "write_accel_ram", 4, 4 },
    [0x40] = { "read_param", 2, 7 },
    [0x42] = { "write_param_ram", 7, 2 },
    [0x44] = { "write_param_rom", 7, 2 },
    [0x80] = { "motor_off", 0, 0 },
    [0x81] = { "motor_stop", 0, 0 },
    [0x88] = { "motor_run", 0, 0 },
    [0x8C] = { "brake", 1, 1 },
    [0x90] = { "read_encoder", 0, 6 },
    [0x91] = { "write_encoder_offset", 2, 2 },
    [0x92] = { "read_multi_turn", 0, 8 },
    [0x93] = { "clear_turn_count", 0, 0 },
    [0x94] = { "read_single_turn", 0, 4 },
    [0x95] = { "clear_angle", 0, 0 },
    [0x9A] = { "read_state1", 0, 7 },
    [0x9B] = { "clear_errors", 0, 7 },
    [0x9C] = { "read_state2", 0, 7 },
    [0x9D] = { "read_state3", 0, 7 },
    [0xA0] = { "open_loop", 2, 7 },
    [0xA1] = { "torque", 2, 7 },
    [0xA2] = { "speed", 4, 7 },
    [0xA3] = { "multi_position", 8, 7 },
    [0xA4] = { "multi_position_limited", 12, 7 },
    [0xA5] = { "single_position", 4, 7 },
    [0xA6] = { "single_position_limited", 8, 7 },
    [0xA7] = { "increment_position", 4, 7 },
    [0xA8] = { "increment_position_limited", 8, 7 },
}
local command_names = {}
for code, c in pairs(commands) do command_names[code] = c[1] end

local param_names = {
    [0x96] = "angle_pid", [0x97] = "speed_pid", [0x98] = "iq_pid", [0x99] = "max_torque",
    [0x9A] = "max_speed", [0x9B] = "max_angle_low", [0x9C] = "max_angle_high",
    [0x9D] = "current_ramp", [0x9E] = "speed_ramp",
}
local brake_names = { [0x00] = "apply", [0x01] = "release", [0x10] = "read" }
local brake_state_names = { [0x00] = "applied", [0x01] = "released" }
local direction_names = { [0] = "clockwise", [1] = "counter-clockwise" }
local motor_state_names = { [0x00] = "on", [0x10] = "off" }

local f = lk.fields
f.wire = ProtoField.uint8("lkservo.wire", "Wire", base.DEC, wire_names)
f.kind = ProtoField.uint8("lkservo.kind", "Direction", base.DEC, kind_names)
f.head = ProtoField.uint8("lkservo.head", "Head", base.HEX)
f.code = ProtoField.uint8("lkservo.code", "Command code", base.HEX, command_names)
f.command = ProtoField.string("lkservo.command", "Command")
f.id = ProtoField.uint8("lkservo.id", "Drive ID")
f.len = ProtoField.uint8("lkservo.len", "Data length")
f.hcs = ProtoField.uint8("lkservo.hcs", "Header checksum", base.HEX)
f.dcs = ProtoField.uint8("lkservo.dcs", "Data checksum", base.HEX)
f.checksum_ok = ProtoField.bool("lkservo.checksum_ok", "Checksums valid")
f.data = ProtoField.bytes("lkservo.data", "Data")
f.generation = ProtoField.string("lkservo.generation", "Generation")
f.series = ProtoField.string("lkservo.series", "Series")
-- State reads and motion replies
f.temperature = ProtoField.int8("lkservo.temperature_c", "Temperature (C)")
f.iq_raw = ProtoField.int16("lkservo.iq_raw", "iq (raw)")
f.iq_a = ProtoField.double("lkservo.iq_a", "iq (A)")
f.power = ProtoField.int16("lkservo.power", "Power (-1000..1000)")
f.speed_dps = ProtoField.int16("lkservo.speed_dps", "Speed (dps)")
f.encoder = ProtoField.uint16("lkservo.encoder", "Encoder")
f.voltage_v = ProtoField.double("lkservo.voltage_v", "Voltage (V)")
f.bus_current_a = ProtoField.double("lkservo.bus_current_a", "Bus current (A)")
f.motor_state = ProtoField.uint8("lkservo.motor_state", "Motor state", base.HEX,
                                 motor_state_names)
f.error_state = ProtoField.uint8("lkservo.error_state", "Error state", base.HEX)
f.err_low_voltage = ProtoField.bool("lkservo.low_voltage", "Low voltage", 8, nil, 0x01)
f.err_over_voltage = ProtoField.bool("lkservo.over_voltage", "Over-voltage", 8, nil, 0x02)
f.err_driver_temp = ProtoField.bool("lkservo.driver_over_temperature",
                                    "Driver over-temperature", 8, nil, 0x04)
f.err_over_temp = ProtoField.bool("lkservo.over_temperature", "(Motor) over-temperature", 8,
                                  nil, 0x08)
f.err_over_current = ProtoField.bool("lkservo.over_current", "Over-current", 8, nil, 0x10)
f.err_short = ProtoField.bool("lkservo.short_circuit", "Short circuit", 8, nil, 0x20)
f.err_stall = ProtoField.bool("lkservo.stall", "Stall", 8, nil, 0x40)
f.err_timeout = ProtoField.bool("lkservo.input_timeout", "Input signal lost", 8, nil, 0x80)
f.ia_a = ProtoField.double("lkservo.ia_a", "Phase A current (A)")
f.ib_a = ProtoField.double("lkservo.ib_a", "Phase B current (A)")
f.ic_a = ProtoField.double("lkservo.ic_a", "Phase C current (A)")
f.phase_raw = ProtoField.int16("lkservo.phase_raw", "Phase current (raw)")
-- Position reads
f.encoder_raw = ProtoField.uint16("lkservo.encoder_raw", "Encoder raw")
f.encoder_offset = ProtoField.uint16("lkservo.encoder_offset", "Encoder offset")
f.angle_raw = ProtoField.int64("lkservo.angle_raw", "Angle (0.01 deg)")
f.angle_deg = ProtoField.double("lkservo.angle_deg", "Angle (deg)")
f.circle_raw = ProtoField.uint32("lkservo.circle_angle_raw", "Single-turn angle (0.01 deg)")
f.circle_deg = ProtoField.double("lkservo.circle_angle_deg", "Single-turn angle (deg)")
-- Model
f.driver_name = ProtoField.string("lkservo.driver_name", "Driver name")
f.motor_name = ProtoField.string("lkservo.motor_name", "Motor name")
f.motor_id = ProtoField.bytes("lkservo.motor_id", "Motor ID")
f.hardware_version = ProtoField.double("lkservo.hardware_version", "Hardware version")
f.firmware_version = ProtoField.double("lkservo.firmware_version", "Firmware version")
f.motor_version = ProtoField.uint16("lkservo.motor_version_raw", "Motor version (raw)")
-- Settings
f.angle_kp = ProtoField.uint8("lkservo.angle_kp", "Angle Kp")
f.angle_ki = ProtoField.uint8("lkservo.angle_ki", "Angle Ki")
f.speed_kp = ProtoField.uint8("lkservo.speed_kp", "Speed Kp")
f.speed_ki = ProtoField.uint8("lkservo.speed_ki", "Speed Ki")
f.iq_kp = ProtoField.uint8("lkservo.iq_kp", "iq Kp")
f.iq_ki = ProtoField.uint8("lkservo.iq_ki", "iq Ki")
f.accel = ProtoField.int32("lkservo.acceleration_dps2", "Acceleration (dps/s)")
f.offset = ProtoField.uint16("lkservo.offset", "Encoder offset")
f.zero = ProtoField.uint16("lkservo.zero", "Stored zero")
f.param_id = ProtoField.uint8("lkservo.param_id", "Parameter", base.HEX, param_names)
f.param_kp = ProtoField.uint16("lkservo.param_kp", "Kp")
f.param_ki = ProtoField.uint16("lkservo.param_ki", "Ki")
f.param_kd = ProtoField.uint16("lkservo.param_kd", "Kd")
f.param_i16 = ProtoField.int16("lkservo.param_int16", "Value (int16)")
f.param_i32 = ProtoField.int32("lkservo.param_int32", "Value (int32)")
f.param_u32 = ProtoField.uint32("lkservo.param_uint32", "Value (uint32)")
f.param_result = ProtoField.uint8("lkservo.param_result", "Result", base.DEC,
                                  { [0] = "success", [1] = "failure" })
f.brake = ProtoField.uint8("lkservo.brake", "Brake", base.HEX, brake_names)
f.brake_state = ProtoField.uint8("lkservo.brake_state", "Brake state", base.HEX,
                                 brake_state_names)
-- Motion commands
f.power_cmd = ProtoField.int16("lkservo.power_command", "Power command")
f.iq_cmd_raw = ProtoField.int16("lkservo.iq_command_raw", "iq command (raw)")
f.iq_cmd_a = ProtoField.double("lkservo.iq_command_a", "iq command (A)")
f.speed_cmd_raw = ProtoField.int32("lkservo.speed_command_raw", "Speed (0.01 dps)")
f.speed_cmd = ProtoField.double("lkservo.speed_command_dps", "Speed (dps)")
f.max_speed_raw = ProtoField.uint32("lkservo.max_speed_raw", "Max speed (0.01 dps)")
f.max_speed = ProtoField.double("lkservo.max_speed_dps", "Max speed (dps)")
f.direction = ProtoField.uint8("lkservo.spin_direction", "Direction", base.DEC, direction_names)
f.increment_raw = ProtoField.int32("lkservo.increment_raw", "Increment (0.01 deg)")
f.increment = ProtoField.double("lkservo.increment_deg", "Increment (deg)")
f.context_entry = ProtoField.string("lkservo.context", "Drive")

-- Preferences: how drives decode when the capture carries no context for them.
lk.prefs.generation = Pref.enum("Default generation", 0, "Protocol generation of drives " ..
    "whose read_model reply is not in the capture",
    { { 1, "v2.3", 0 }, { 2, "v2.35", 1 } }, false)
lk.prefs.ms_ids = Pref.string("MS drive IDs", "", "Comma-separated IDs of MS drives " ..
    "(their replies carry power, not iq) when the capture carries no context")

-- Decode context learnt in capture order; per packet, the context it saw (so a second pass
-- and random access decode as the first, sequential one did).
local context = {}
local seen = {}

local function reset_state()
    context = {}
    seen = {}
end
lk.init = reset_state

local function drive_context(id)
    local c = context[id]
    local series = c and c.series or 0
    if series == 0 then
        for s in string.gmatch(lk.prefs.ms_ids, "%d+") do
            if tonumber(s) == id then series = 1 end
        end
    end
    local generation = c and c.generation or lk.prefs.generation
    return { series = series, generation = generation }
end

local function iq_reply_scale(ctx)
    if ctx.generation == 1 and ctx.series == 2 then return 33.0 / 4096.0 end
    return 33.0 / 2048.0
end

local function iq_command_scale(ctx)
    if ctx.generation == 1 then return iq_reply_scale(ctx) end
    return 32.0 / 2000.0
end

local function phase_scale(ctx)
    if ctx.generation == 1 then return iq_reply_scale(ctx) end
    return 1.0 / 64.0
end

local function int64_value(range)
    return range:le_int64()
end

-- Layouts ------------------------------------------------------------------------------------

local function state2(t, d, code, ctx)
    t:add_le(f.temperature, d(0, 1))
    local power = code == 0xA0 or (code ~= 0xA1 and ctx.series == 1)
    if power then
        t:add_le(f.power, d(1, 2))
    else
        t:add_le(f.iq_raw, d(1, 2))
        t:add(f.iq_a, d(1, 2), d(1, 2):le_int() * iq_reply_scale(ctx))
    end
    t:add_le(f.speed_dps, d(3, 2))
    t:add_le(f.encoder, d(5, 2))
end

local function error_bits(t, range)
    local e = t:add(f.error_state, range)
    for _, field in ipairs({ f.err_low_voltage, f.err_over_voltage, f.err_driver_temp,
                             f.err_over_temp, f.err_over_current, f.err_short, f.err_stall,
                             f.err_timeout }) do
        e:add(field, range)
    end
end

local function state1(t, d, ctx)
    t:add_le(f.temperature, d(0, 1))
    if ctx.generation == 1 then
        t:add(f.voltage_v, d(1, 2), d(1, 2):le_int() * 0.01)
        t:add(f.bus_current_a, d(3, 2), d(3, 2):le_int() * 0.01)
        t:add(f.motor_state, d(5, 1))
    else
        t:add(f.voltage_v, d(2, 2), d(2, 2):le_uint() * 0.1)
    end
    error_bits(t, d(6, 1))
end

local function state3(t, d, ctx)
    t:add_le(f.temperature, d(0, 1))
    local scale = phase_scale(ctx)
    for i, field in ipairs({ f.ia_a, f.ib_a, f.ic_a }) do
        local r = d(1 + 2 * (i - 1), 2)
        t:add(field, r, r:le_int() * scale)
    end
end

local function model(t, d, len)
    t:add(f.driver_name, d(0, 20), d(0, 20):stringz())
    t:add(f.motor_name, d(20, 20), d(20, 20):stringz())
    if len == 42 then
        t:add(f.hardware_version, d(40, 1), d(40, 1):uint() / 10.0)
        t:add(f.firmware_version, d(41, 1), d(41, 1):uint() / 10.0)
    else
        t:add(f.motor_id, d(40, 12))
        t:add(f.hardware_version, d(52, 2), d(52, 2):le_uint() / 100.0)
        t:add_le(f.motor_version, d(54, 2))
        t:add(f.firmware_version, d(56, 2), d(56, 2):le_uint() / 100.0)
    end
end

local function pid(t, d)
    for i, field in ipairs({ f.angle_kp, f.angle_ki, f.speed_kp, f.speed_ki, f.iq_kp, f.iq_ki }) do
        t:add(field, d(i - 1, 1))
    end
end

local function param_value(t, d)
    local id = d(0, 1):uint()
    t:add(f.param_id, d(0, 1))
    if id >= 0x96 and id <= 0x98 then
        t:add_le(f.param_kp, d(1, 2))
        t:add_le(f.param_ki, d(3, 2))
        t:add_le(f.param_kd, d(5, 2))
    elseif id == 0x99 or id == 0x9D then
        t:add_le(f.param_i16, d(1, 2))
    elseif id == 0x9A then
        t:add_le(f.max_speed_raw, d(1, 4))
        t:add(f.max_speed, d(1, 4), d(1, 4):le_uint() / 100.0)
    elseif id == 0x9B or id == 0x9C then
        t:add_le(f.param_u32, d(1, 4))
    elseif id == 0x9E then
        t:add_le(f.param_i32, d(1, 4))
    end
end

local function angle(t, r)
    t:add_le(f.angle_raw, r)
    t:add(f.angle_deg, r, int64_value(r):tonumber() / 100.0)
end

local function max_speed(t, r)
    t:add_le(f.max_speed_raw, r)
    t:add(f.max_speed, r, r:le_uint() / 100.0)
end

local function single_angle(t, d)
    t:add(f.direction, d(0, 1))
    t:add(f.circle_raw, d(1, 3), d(1, 3):le_uint())
    t:add(f.circle_deg, d(1, 3), d(1, 3):le_uint() / 100.0)
end

local function increment(t, r)
    t:add_le(f.increment_raw, r)
    t:add(f.increment, r, r:le_int() / 100.0)
end

-- A request's data (or an echo, read as the request it repeats).
local function request_fields(t, code, d, ctx)
    if code == 0x31 or code == 0x32 then pid(t, d)
    elseif code == 0x34 then t:add_le(f.accel, d(0, 4))
    elseif code == 0x91 then t:add_le(f.offset, d(0, 2))
    elseif code == 0x40 then t:add(f.param_id, d(0, 1))
    elseif code == 0x42 or code == 0x44 then param_value(t, d)
    elseif code == 0x8C then t:add(f.brake, d(0, 1))
    elseif code == 0xA0 then t:add_le(f.power_cmd, d(0, 2))
    elseif code == 0xA1 then
        t:add_le(f.iq_cmd_raw, d(0, 2))
        t:add(f.iq_cmd_a, d(0, 2), d(0, 2):le_int() * iq_command_scale(ctx))
    elseif code == 0xA2 then
        t:add_le(f.speed_cmd_raw, d(0, 4))
        t:add(f.speed_cmd, d(0, 4), d(0, 4):le_int() / 100.0)
    elseif code == 0xA3 then angle(t, d(0, 8))
    elseif code == 0xA4 then
        angle(t, d(0, 8))
        max_speed(t, d(8, 4))
    elseif code == 0xA5 then single_angle(t, d)
    elseif code == 0xA6 then
        single_angle(t, d)
        max_speed(t, d(4, 4))
    elseif code == 0xA7 then increment(t, d(0, 4))
    elseif code == 0xA8 then
        increment(t, d(0, 4))
        max_speed(t, d(4, 4))
    end
end

local function reply_fields(t, code, d, len, ctx)
    if code == 0x9C or (code >= 0xA0 and code <= 0xA8) then state2(t, d, code, ctx)
    elseif code == 0x9A or code == 0x9B then state1(t, d, ctx)
    elseif code == 0x9D then state3(t, d, ctx)
    elseif code == 0x12 then model(t, d, len)
    elseif code == 0x30 then pid(t, d)
    elseif code == 0x33 then t:add_le(f.accel, d(0, 4))
    elseif code == 0x90 then
        t:add_le(f.encoder, d(0, 2))
        t:add_le(f.encoder_raw, d(2, 2))
        t:add_le(f.encoder_offset, d(4, 2))
    elseif code == 0x92 then angle(t, d(0, 8))
    elseif code == 0x94 then
        t:add_le(f.circle_raw, d(0, 4))
        t:add(f.circle_deg, d(0, 4), d(0, 4):le_uint() / 100.0)
    elseif code == 0x19 and len == 2 then t:add_le(f.zero, d(0, 2))
    elseif code == 0x40 then param_value(t, d)
    elseif code == 0x42 or code == 0x44 then
        t:add(f.param_id, d(0, 1))
        t:add(f.param_result, d(1, 1))
    elseif code == 0x8C then t:add(f.brake_state, d(0, 1))
    end
end

local function dissect_context(tvb, tree)
    local t = tree:add(lk, tvb(), "LK servo decode context")
    for i = 2, tvb:len() - 3, 3 do
        local id = tvb(i, 1):uint()
        local series = tvb(i + 1, 1):uint()
        local generation = tvb(i + 2, 1):uint()
        context[id] = { series = series, generation = generation }
        t:add(f.context_entry, tvb(i, 3), string.format("ID %d: %s, %s", id,
              series_names[series] or "?", generation_names[generation] or "?"))
    end
end

function lk.dissector(tvb, pinfo, tree)
    if tvb:len() < 2 then return 0 end
    pinfo.cols.protocol = "LK servo"
    local wire = tvb(0, 1):uint()
    local kind = tvb(1, 1):uint()
    if kind == 4 then
        if not pinfo.visited then dissect_context(tvb, tree) else
            tree:add(lk, tvb(), "LK servo decode context") end
        pinfo.cols.info = "decode context"
        return tvb:len()
    end
    local t = tree:add(lk, tvb(), "LK servo RS485")
    t:add(f.wire, tvb(0, 1))
    t:add(f.kind, tvb(1, 1))
    local frame = tvb(2):tvb()
    local n = frame:len()
    if kind == 3 or n < 5 then
        pinfo.cols.info = string.format("%s: %d bytes that form no frame", wire_names[wire] or "?", n)
        t:add(f.data, tvb(2))
        return tvb:len()
    end
    local code = frame(1, 1):uint()
    local id = frame(2, 1):uint()
    local len = frame(3, 1):uint()
    t:add(f.head, frame(0, 1))
    t:add(f.code, frame(1, 1))
    local c = commands[code]
    local name = c and c[1] or string.format("0x%02X", code)
    t:add(f.command, frame(1, 1), name)
    t:add(f.id, frame(2, 1))
    t:add(f.len, frame(3, 1))
    t:add(f.hcs, frame(4, 1))
    local ok = (0x3E + code + id + len) % 256 == frame(4, 1):uint()
    if len > 0 and n >= len + 6 then
        local sum = 0
        for i = 5, 4 + len do sum = sum + frame(i, 1):uint() end
        ok = ok and sum % 256 == frame(5 + len, 1):uint()
        t:add(f.dcs, frame(5 + len, 1))
    end
    t:add(f.checksum_ok, frame(4, 1), ok)

    -- The context of this packet: learnt once, in capture order.
    if not pinfo.visited then
        if kind == 1 and code == 0x12 then
            local ctx = context[id] or { series = 0 }
            ctx.generation = len == 58 and 1 or 0
            context[id] = ctx
        end
        seen[pinfo.number] = drive_context(id)
    end
    local ctx = seen[pinfo.number] or drive_context(id)
    t:add(f.generation, frame(2, 1), generation_names[ctx.generation] or "?"):set_generated()
    t:add(f.series, frame(2, 1), series_names[ctx.series] or "?"):set_generated()

    if len > 0 and n >= len + 6 then
        local data = frame(5, len):tvb()
        local d = function(o, l) return data(o, l) end
        local ft = t:add(f.data, frame(5, len))
        if kind == 1 then
            reply_fields(ft, code, d, len, ctx)
        else
            request_fields(ft, code, d, ctx)
        end
    end
    pinfo.cols.info = string.format("%s %s %s ID %d", wire_names[wire] or "?",
                                    kind_names[kind] or "?", name, id)
    return tvb:len()
end

DissectorTable.get("wtap_encap"):add(wtap.USER0, lk)
