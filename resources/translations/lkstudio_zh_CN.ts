<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>GenerationNote</name>
    <message>
        <source>The protocol generation of this drive is not known (its model was not read), so %1 (%2), a V2.35 command, is not offered. Nothing is sent.</source>
        <translation>此驱动的协议版本未知（未读到其型号），因此不提供 V2.35 命令 %1 (%2)。不发送任何命令。</translation>
    </message>
    <message>
        <source>This drive speaks protocol %1, which has no %2 command (%3): it came with V2.35 (firmware 2.35 and later). Nothing is sent.</source>
        <translation>此驱动使用协议 %1，该协议没有%2命令 (%3)：它随 V2.35（固件 2.35 及更高版本）引入。不发送任何命令。</translation>
    </message>
    <message>
        <source>The protocol generation of this drive is not known yet (CAN has no model read: choose it, or wait for its replies), so %1 (%2) is not offered. Nothing is sent.</source>
        <translation>此驱动器的协议版本尚未可知（CAN 没有型号读取：请选择它，或等待它的回复），因此不提供%1（%2）。未发送任何内容。</translation>
    </message>
    <message>
        <source>This drive speaks %1, which has no %2 command (%3). Nothing is sent.</source>
        <translation>此驱动器使用 %1，该协议没有%2命令（%3）。未发送任何内容。</translation>
    </message>
</context>
<context>
    <name>lk::bus::BusSession</name>
    <message>
        <source>session closed</source>
        <translation>会话已关闭</translation>
    </message>
    <message>
        <source>the bus is not open</source>
        <translation>总线未打开</translation>
    </message>
</context>
<context>
    <name>lk::bus::BusWorker</name>
    <message>
        <source>bus closed</source>
        <translation>总线已关闭</translation>
    </message>
    <message>
        <source>the port was reopened at another baud</source>
        <translation>串口已按其他波特率重新打开</translation>
    </message>
    <message>
        <source>open</source>
        <translation>已打开</translation>
    </message>
    <message>
        <source>the bus is not open</source>
        <translation>总线未打开</translation>
    </message>
    <message>
        <source>cancelled by emergency stop</source>
        <translation>已被急停取消</translation>
    </message>
    <message>
        <source>scan cancelled</source>
        <translation>扫描已取消</translation>
    </message>
    <message>
        <source>setpoint stream stopped</source>
        <translation>设定值流已停止</translation>
    </message>
    <message>
        <source>cancelled: drive %1 went past its speed limit</source>
        <translation>已取消：驱动器 %1 超过了速度限制</translation>
    </message>
    <message>
        <source>%1 to drive %2 was not sent: %3</source>
        <translation>%1 未发送到驱动器 %2：%3</translation>
    </message>
    <message>
        <source>the multi-motor torque frame could not be encoded; nothing was sent</source>
        <translation>无法编码多电机转矩帧；未发送任何内容</translation>
    </message>
</context>
<context>
    <name>lk::bus::DriveIdentity</name>
    <message>
        <source>&quot;%1&quot;: write ID:SERIES@GENERATION, e.g. 3:MG@2.35 or 1:MF@can236</source>
        <translation>“%1”：请写成 ID:系列@代次，例如 3:MG@2.35 或 1:MF@can236</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the ID must be 1..32</source>
        <translation>“%1”：ID 必须在 1..32 之间</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the series must be MS, MF, MG or MH</source>
        <translation>“%1”：系列必须是 MS、MF、MG 或 MH</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the gear ratio after / must be a number of 1 or more</source>
        <translation>“%1”：/ 后的减速比必须是不小于 1 的数字</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the generation must be 2.3 or 2.35 (RS485), can (old CAN) or can236 (CAN V2.36)</source>
        <translation>“%1”：代次必须是 2.3 或 2.35（RS485）、can（旧版 CAN）或 can236（CAN V2.36）</translation>
    </message>
    <message>
        <source>drive %1 is named twice</source>
        <translation>驱动器 %1 被指定了两次</translation>
    </message>
    <message>
        <source>no drive given: write ID:SERIES@GENERATION,..., e.g. 3:MG@2.35</source>
        <translation>未指定驱动器：请写成 ID:系列@代次,...，例如 3:MG@2.35</translation>
    </message>
</context>
<context>
    <name>lk::bus::LinkMode</name>
    <message>
        <source>listen-only: nothing was sent</source>
        <translation>仅监听：未发送任何数据</translation>
    </message>
</context>
<context>
    <name>lk::bus::MotorRegistry</name>
    <message>
        <source>drive %1 runs firmware 2.35 or later (protocol V2.35), which has no %2; nothing was sent</source>
        <translation>驱动器 %1 运行 2.35 或更高版本固件（V2.35 协议），该协议没有 %2；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1 speaks protocol V2.3, which has no %2 (firmware 2.35 added it); nothing was sent</source>
        <translation>驱动器 %1 使用 V2.3 协议，该协议没有 %2（2.35 固件才加入）；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1 speaks %2, which has no %3; nothing was sent</source>
        <translation>驱动器 %1 使用 %2，该协议没有 %3；未发送任何内容</translation>
    </message>
</context>
<context>
    <name>lk::bus::Scanner</name>
    <message>
        <source>scan range %1..%2 is outside 1..32</source>
        <translation>扫描范围 %1..%2 超出 1..32</translation>
    </message>
    <message>
        <source>no valid baud to scan</source>
        <translation>没有可扫描的有效波特率</translation>
    </message>
</context>
<context>
    <name>lk::bus::TelemetryFieldInfo</name>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Error flags</source>
        <translation>错误标志</translation>
    </message>
    <message>
        <source>iq</source>
        <translation>iq</translation>
    </message>
    <message>
        <source>Power</source>
        <translation>功率</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>编码器</translation>
    </message>
    <message>
        <source>Multi-turn angle</source>
        <translation>多圈角度</translation>
    </message>
    <message>
        <source>Single-turn angle</source>
        <translation>单圈角度</translation>
    </message>
    <message>
        <source>Phase A</source>
        <translation>A 相电流</translation>
    </message>
    <message>
        <source>Phase B</source>
        <translation>B 相电流</translation>
    </message>
    <message>
        <source>Phase C</source>
        <translation>C 相电流</translation>
    </message>
    <message>
        <source>Bus current</source>
        <translation>母线电流</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>电机</translation>
    </message>
    <message>
        <source>Commanded iq</source>
        <translation>指令 iq</translation>
    </message>
    <message>
        <source>Commanded power</source>
        <translation>指令功率</translation>
    </message>
    <message>
        <source>Commanded speed</source>
        <translation>指令速度</translation>
    </message>
    <message>
        <source>Commanded angle</source>
        <translation>指令角度</translation>
    </message>
    <message>
        <source>Commanded single-turn angle</source>
        <translation>指令单圈角度</translation>
    </message>
    <message>
        <source>Commanded direction</source>
        <translation>指令方向</translation>
    </message>
    <message>
        <source>Commanded increment</source>
        <translation>指令增量</translation>
    </message>
    <message>
        <source>Commanded speed limit</source>
        <translation>指令限速</translation>
    </message>
</context>
<context>
    <name>lk::bus::TrafficRecorder</name>
    <message>
        <source>%1 traffic events dropped (view too slow)</source>
        <translation>丢弃了 %1 条通信记录（视图刷新过慢）</translation>
    </message>
</context>
<context>
    <name>lk::bus::TransportLink</name>
    <message>
        <source>No transport: the transport factory returned nothing.</source>
        <translation>没有可用的传输通道：传输工厂未返回任何对象。</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>已关闭</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>已断开</translation>
    </message>
</context>
<context>
    <name>lk::bus::WireEncoding</name>
    <message>
        <source>not known: a CAN V2.36 speed command carries a torque limit scaled by it</source>
        <translation>未知：CAN V2.36 的速度指令携带按系列换算的转矩限制</translation>
    </message>
</context>
<context>
    <name>lk::bus::WireExchange</name>
    <message numerus="yes">
        <source>no reply to %1 after %n attempt(s)</source>
        <translation>
            <numerusform>%1 无回复（已尝试 %n 次）</numerusform>
        </translation>
    </message>
    <message>
        <source>corrupt reply to %1 (bad data checksum)</source>
        <translation>%1 的回复已损坏（数据校验和错误）</translation>
    </message>
    <message>
        <source>undecodable reply to %1</source>
        <translation>%1 的回复无法解码</translation>
    </message>
    <message>
        <source>no reply from drive(s) %1 to the multi-motor torque frame (0x280): not in its Broadcast Mode, or absent</source>
        <translation>驱动器 %1 未应答多电机转矩帧（0x280）：未处于广播模式，或不存在</translation>
    </message>
</context>
<context>
    <name>lk::fleet::BackupFile</name>
    <message>
        <source>a number in %1..%2</source>
        <translation>%1..%2 之间的数值</translation>
    </message>
    <message>
        <source>text in quotes</source>
        <translation>带引号的文本</translation>
    </message>
    <message>
        <source>an object ({ ... })</source>
        <translation>对象（{ ... }）</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is too large to be a backup (more than %2 bytes)</source>
        <translation>%1 太大，不可能是备份文件（超过 %2 字节）</translation>
    </message>
    <message>
        <source>damaged or truncated: not valid JSON (%1 at byte %2)</source>
        <translation>文件已损坏或被截断：不是有效的 JSON（第 %2 字节处：%1）</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>不是 JSON 对象</translation>
    </message>
    <message>
        <source>format is %1, not &quot;%2&quot;: not a bus backup</source>
        <translation>format 为 %1，而不是 &quot;%2&quot;：不是总线备份文件</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <source>version is %1: written by a newer release (this one reads up to %2)</source>
        <translation>version 为 %1：由更新的版本写入（本版本最高读取 %2）</translation>
    </message>
    <message>
        <source>%1 is missing: it must be %2</source>
        <translation>缺少 %1：它必须是%2</translation>
    </message>
    <message>
        <source>%1 is not a key of a bus backup here</source>
        <translation>%1 不是总线备份在此处的键</translation>
    </message>
    <message>
        <source>%1 is given twice: which one is meant is not known</source>
        <translation>%1 出现了两次：无法确定以哪一个为准</translation>
    </message>
    <message>
        <source>%1 is %2: it must be %3</source>
        <translation>%1 为 %2：它必须是%3</translation>
    </message>
    <message>
        <source>%1 is %2, out of range: it must be %3</source>
        <translation>%1 为 %2，超出范围：它必须是%3</translation>
    </message>
    <message>
        <source>%1 is %2: it must be MS, MF, MG or MH</source>
        <translation>%1 为 %2：它必须是 MS、MF、MG 或 MH</translation>
    </message>
    <message>
        <source>%1 is %2: it must be &quot;v2.3&quot; or &quot;v2.35&quot;</source>
        <translation>%1 为 %2：必须是 &quot;v2.3&quot; 或 &quot;v2.35&quot;</translation>
    </message>
    <message>
        <source>%1 is %2: it must be a date and time such as &quot;2026-05-04T03:02:01.000Z&quot;</source>
        <translation>%1 为 %2：它必须是日期时间，例如“2026-05-04T03:02:01.000Z”</translation>
    </message>
</context>
<context>
    <name>lk::fleet::IdMap</name>
    <message>
        <source>&apos;%1&apos; is not a drive ID 1..32 or a range such as 1-4 (all, 3, 1,2,5 or 1-4)</source>
        <translation>“%1”不是 1..32 之间的驱动 ID，也不是 1-4 这样的范围（all、3、1,2,5 或 1-4）</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not OLD:NEW with two drive IDs 1..32 (e.g. 3:5,4:6)</source>
        <translation>“%1”不是由两个 1..32 之间的驱动 ID 组成的 旧:新 格式（例如 3:5,4:6）</translation>
    </message>
    <message>
        <source>&apos;%1&apos; maps a drive that is already mapped</source>
        <translation>“%1”映射了一个已经映射过的驱动</translation>
    </message>
</context>
<context>
    <name>lk::protocol::ErrorFlags</name>
    <message>
        <source>low voltage</source>
        <translation>低压保护</translation>
    </message>
    <message>
        <source>over-temperature</source>
        <translation>过温保护</translation>
    </message>
    <message>
        <source>over-voltage</source>
        <translation>过压保护</translation>
    </message>
    <message>
        <source>driver over-temperature</source>
        <translation>驱动器过温保护</translation>
    </message>
    <message>
        <source>motor over-temperature</source>
        <translation>电机过温保护</translation>
    </message>
    <message>
        <source>over-current</source>
        <translation>过流保护</translation>
    </message>
    <message>
        <source>short circuit</source>
        <translation>短路保护</translation>
    </message>
    <message>
        <source>stall</source>
        <translation>堵转保护</translation>
    </message>
    <message>
        <source>input signal lost (timeout)</source>
        <translation>输入信号丢失（超时）</translation>
    </message>
</context>
<context>
    <name>lk::protocol::FieldError</name>
    <message>
        <source>%1 must be in %2</source>
        <translation>%1 必须在 %2 范围内</translation>
    </message>
</context>
<context>
    <name>lk::protocol::FieldText</name>
    <message>
        <source>angle Kp %1 Ki %2, speed Kp %3 Ki %4, iq Kp %5 Ki %6</source>
        <translation>角度环 Kp %1 Ki %2，速度环 Kp %3 Ki %4，电流环 Kp %5 Ki %6</translation>
    </message>
    <message>
        <source>, max %1 dps</source>
        <translation>，最大 %1 dps</translation>
    </message>
    <message>
        <source>accel %1 dps/s</source>
        <translation>加速度 %1 dps/s</translation>
    </message>
    <message>
        <source>offset %1</source>
        <translation>零偏 %1</translation>
    </message>
    <message>
        <source>power %1</source>
        <translation>功率 %1</translation>
    </message>
    <message>
        <source>iq %1 A</source>
        <translation>转矩电流 %1 A</translation>
    </message>
    <message>
        <source>speed %1 dps</source>
        <translation>速度 %1 dps</translation>
    </message>
    <message>
        <source>angle %1 deg</source>
        <translation>角度 %1°</translation>
    </message>
    <message>
        <source>cw</source>
        <translation>顺时针</translation>
    </message>
    <message>
        <source>ccw</source>
        <translation>逆时针</translation>
    </message>
    <message>
        <source>%1 to %2 deg</source>
        <translation>%1转到 %2°</translation>
    </message>
    <message>
        <source>by %1%2 deg</source>
        <translation>增量 %1%2°</translation>
    </message>
    <message>
        <source>T %1 C</source>
        <translation>温度 %1 °C</translation>
    </message>
    <message>
        <source>error bits 0x%1</source>
        <translation>错误位 0x%1</translation>
    </message>
    <message>
        <source>%1, %2, %3 dps, enc %4</source>
        <translation>%1，%2，%3 dps，编码器 %4</translation>
    </message>
    <message>
        <source>%1 / %2, hw %3, fw %4</source>
        <translation>%1 / %2，硬件 %3，固件 %4</translation>
    </message>
    <message>
        <source>enc %1, raw %2, offset %3</source>
        <translation>编码器 %1，原始值 %2，零偏 %3</translation>
    </message>
    <message>
        <source>%1, ia %2 A, ib %3 A, ic %4 A</source>
        <translation>%1，A 相 %2 A，B 相 %3 A，C 相 %4 A</translation>
    </message>
    <message>
        <source>%1 Kp %2 Ki %3 Kd %4</source>
        <translation>%1 Kp %2 Ki %3 Kd %4</translation>
    </message>
    <message>
        <source>engage brake</source>
        <translation>抱闸锁紧</translation>
    </message>
    <message>
        <source>release brake</source>
        <translation>抱闸释放</translation>
    </message>
    <message>
        <source>read brake</source>
        <translation>读取抱闸状态</translation>
    </message>
    <message>
        <source>motor on</source>
        <translation>电机运行</translation>
    </message>
    <message>
        <source>motor off</source>
        <translation>电机关闭</translation>
    </message>
    <message>
        <source>%1 written</source>
        <translation>%1 已写入</translation>
    </message>
    <message>
        <source>%1 refused (flag %2)</source>
        <translation>%1 被拒绝（标志 %2）</translation>
    </message>
    <message>
        <source>brake released</source>
        <translation>抱闸已释放</translation>
    </message>
    <message>
        <source>brake applied</source>
        <translation>抱闸已锁紧</translation>
    </message>
    <message>
        <source>%1 %2 (unit unknown)</source>
        <translation>%1 %2（单位未知）</translation>
    </message>
    <message>
        <source>position := %1 deg</source>
        <translation>位置设为 %1°</translation>
    </message>
</context>
<context>
    <name>lk::protocol::LinkCodec</name>
    <message>
        <source>%1 exists on CAN V2.36 only</source>
        <translation>%1 仅在 CAN V2.36 上存在</translation>
    </message>
</context>
<context>
    <name>lk::protocol::ProtocolFields</name>
    <message>
        <source>max torque current</source>
        <translation>最大转矩电流</translation>
    </message>
    <message>
        <source>max power</source>
        <translation>最大功率</translation>
    </message>
</context>
<context>
    <name>lk::protocol::RequestBuilder</name>
    <message>
        <source>got %1</source>
        <translation>实际为 %1</translation>
    </message>
</context>
<context>
    <name>lk::protocol::can::CanLayout</name>
    <message>
        <source>got %1 dps: CAN carries whole dps</source>
        <translation>实际为 %1 dps：CAN 只能传送整数 dps</translation>
    </message>
    <message>
        <source>got %1</source>
        <translation>实际为 %1</translation>
    </message>
    <message>
        <source>none given: CAN V2.36 speed commands carry the torque limit of the soft limits</source>
        <translation>未给出：CAN V2.36 的速度命令必须带有软限位中的转矩限制</translation>
    </message>
    <message>
        <source>got %1 deg: CAN carries an int32 angle</source>
        <translation>实际为 %1 deg：CAN 的角度为 int32</translation>
    </message>
    <message>
        <source>got %1 deg</source>
        <translation>实际为 %1 deg</translation>
    </message>
    <message>
        <source>%1 is not on this link</source>
        <translation>%1 在此链路上不可用</translation>
    </message>
    <message>
        <source>got %1 for ID %2</source>
        <translation>ID %2 实际为 %1</translation>
    </message>
</context>
<context>
    <name>lk::record::BusReport</name>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>Driver</source>
        <translation>驱动</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>电机</translation>
    </message>
    <message>
        <source>Hardware</source>
        <translation>硬件</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>LK bus report</source>
        <translation>LK 总线报告</translation>
    </message>
    <message>
        <source>Created: %1 (UTC)</source>
        <translation>生成时间：%1 (UTC)</translation>
    </message>
    <message>
        <source>Connection: %1</source>
        <translation>连接：%1</translation>
    </message>
    <message>
        <source>Drives: %1</source>
        <translation>驱动数：%1</translation>
    </message>
    <message>
        <source>Written by: %1</source>
        <translation>生成工具：%1</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>协议</translation>
    </message>
    <message>
        <source>Gains (angle · speed · iq: Kp/Ki, V2.35 Kp/Ki/Kd)</source>
        <translation>增益（角度 · 速度 · iq：Kp/Ki，V2.35 为 Kp/Ki/Kd）</translation>
    </message>
    <message>
        <source>Acceleration or limits</source>
        <translation>加速度或限值</translation>
    </message>
    <message>
        <source>unknown bits 0x%1</source>
        <translation>未知位 0x%1</translation>
    </message>
    <message>
        <source>%1 dps/s</source>
        <translation>%1 dps/s</translation>
    </message>
    <message>
        <source>max power %1</source>
        <translation>最大功率 %1</translation>
    </message>
    <message>
        <source>max torque %1</source>
        <translation>最大转矩 %1</translation>
    </message>
    <message>
        <source>max speed %1 dps</source>
        <translation>最大速度 %1 dps</translation>
    </message>
    <message>
        <source>max angle %1°</source>
        <translation>最大角度 %1°</translation>
    </message>
    <message>
        <source>current ramp %1</source>
        <translation>电流斜率 %1</translation>
    </message>
    <message>
        <source>speed ramp %1 dps/s</source>
        <translation>速度斜率 %1 dps/s</translation>
    </message>
</context>
<context>
    <name>lk::record::CsvWriter</name>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>The file was not opened</source>
        <translation>文件未打开</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>lk::record::ParameterSet</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>lk::recording</name>
    <message>
        <source>Recorder dropped %1 bytes in %2 chunks (the disk could not keep up)</source>
        <translation>记录器丢弃了 %1 字节，共 %2 块（磁盘写入跟不上）</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>Closed %1</source>
        <translation>已关闭 %1</translation>
    </message>
    <message>
        <source>Baud changed to %1</source>
        <translation>波特率改为 %1</translation>
    </message>
    <message>
        <source>Link error: %1</source>
        <translation>链路错误：%1</translation>
    </message>
    <message>
        <source>Link lost: %1</source>
        <translation>链路丢失：%1</translation>
    </message>
</context>
<context>
    <name>lk::recording::RecordFile</name>
    <message>
        <source>Cannot create the recording %1: %2.</source>
        <translation>无法创建记录文件 %1：%2。</translation>
    </message>
    <message>
        <source>Recording stopped: the disk holding %1 is full (%2).</source>
        <translation>记录已停止：%1 所在的磁盘已满（%2）。</translation>
    </message>
    <message>
        <source>Recording stopped: cannot write %1 (%2).</source>
        <translation>记录已停止：无法写入 %1（%2）。</translation>
    </message>
</context>
<context>
    <name>lk::recording::RecordingReader</name>
    <message>
        <source>Cannot open the recording %1: %2.</source>
        <translation>无法打开记录文件 %1：%2。</translation>
    </message>
    <message>
        <source>standard input</source>
        <translation>标准输入</translation>
    </message>
    <message>
        <source>%1 is not an LK Servo Studio recording (no recording magic).</source>
        <translation>%1 不是 LK Servo Studio 记录文件（没有记录文件标识）。</translation>
    </message>
    <message>
        <source>The recording %1 ends inside its header, at byte offset %2.</source>
        <translation>记录文件 %1 在文件头内结束，位于字节偏移 %2。</translation>
    </message>
    <message>
        <source>The recording %1 has format version %2; this build reads version %3.</source>
        <translation>记录文件 %1 的格式版本为 %2；本版本只能读取版本 %3。</translation>
    </message>
    <message>
        <source>The header of the recording %1 is damaged (checksum or layout).</source>
        <translation>记录文件 %1 的文件头已损坏（校验和或布局错误）。</translation>
    </message>
    <message>
        <source>The recording %1 ends inside a block at byte offset %2 (the writer stopped there); it was read up to that point.</source>
        <translation>记录文件 %1 在字节偏移 %2 处的数据块内结束（写入在此中断）；已读取到该位置。</translation>
    </message>
    <message>
        <source>The recording %1 is damaged at byte offset %2 (%3); it was read up to that point.</source>
        <translation>记录文件 %1 在字节偏移 %2 处损坏（%3）；已读取到该位置。</translation>
    </message>
    <message>
        <source>no block starts there</source>
        <translation>该处不是数据块的开头</translation>
    </message>
    <message>
        <source>impossible block length</source>
        <translation>数据块长度不可能</translation>
    </message>
    <message>
        <source>block checksum mismatch</source>
        <translation>数据块校验和不符</translation>
    </message>
    <message>
        <source>The recording %1 is damaged at byte offset %2 (a record&apos;s layout is wrong); it was read up to that point.</source>
        <translation>记录文件 %1 在字节偏移 %2 处损坏（某条记录的布局错误）；已读取到该位置。</translation>
    </message>
</context>
<context>
    <name>lk::recording::ReplayTransport</name>
    <message>
        <source>Recording %1 (replay)</source>
        <translation>记录文件 %1（回放）</translation>
    </message>
</context>
<context>
    <name>lk::recording::SessionRecorder</name>
    <message>
        <source>The session goes on without recording.</source>
        <translation>会话继续进行，但不再记录。</translation>
    </message>
</context>
<context>
    <name>lk::safety::DriveLimits</name>
    <message>
        <source>the max speed %1 dps is over the drive&apos;s own Max Speed of %2 dps (read from it), which is lower than your speed limit</source>
        <translation>最大速度 %1 dps 超过驱动器自身的最大速度 %2 dps（从驱动器读取），它低于您的速度限制</translation>
    </message>
    <message>
        <source>the speed %1 dps is over the drive&apos;s own Max Speed of %2 dps (read from it), which is lower than your speed limit</source>
        <translation>速度 %1 dps 超过驱动器自身的最大速度 %2 dps（从驱动器读取），它低于您的速度限制</translation>
    </message>
    <message>
        <source>the torque current %1 A is over the drive&apos;s own max torque current of %2 A (read from it), which is lower than your torque limit</source>
        <translation>转矩电流 %1 A 超过驱动器自身的最大转矩电流 %2 A（从驱动器读取），它低于您的转矩限制</translation>
    </message>
    <message>
        <source>the open-loop power %1 is over the drive&apos;s own Max Power of %2 (read from it), which is lower than your power limit</source>
        <translation>开环功率 %1 超过驱动器自身的最大功率 %2（从驱动器读取），它低于您的功率限制</translation>
    </message>
    <message>
        <source>the target %1° is outside the drive&apos;s own Max Angle of ±%2° (read from it), which is narrower than your angle range</source>
        <translation>目标 %1° 超出驱动器自身的最大角度 ±%2°（从驱动器读取），它比您的角度范围更窄</translation>
    </message>
    <message>
        <source>within the drive&apos;s own Max Speed of %1 dps (read from it)</source>
        <translation>在驱动器自身的最大速度 %1 dps 之内（从驱动器读取）</translation>
    </message>
    <message>
        <source>max speed %1 dps (the drive&apos;s own Max Speed, read from it)</source>
        <translation>最大速度 %1 dps（驱动器自身的最大速度，从驱动器读取）</translation>
    </message>
</context>
<context>
    <name>lk::safety::MultiTorqueGuard</name>
    <message>
        <source>the multi-motor torque frame names no drive; nothing was sent</source>
        <translation>多电机转矩帧未指定任何驱动器；未发送任何内容</translation>
    </message>
    <message>
        <source>the multi-motor torque frame carries at most 4 drives (IDs 1..4); nothing was sent</source>
        <translation>多电机转矩帧最多承载 4 个驱动器（ID 1..4）；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: the multi-motor torque frame (0x280) has slots for IDs 1..4 only; nothing was sent</source>
        <translation>驱动器 %1：多电机转矩帧（0x280）只有 ID 1..4 的位置；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1 is named twice; nothing was sent</source>
        <translation>驱动器 %1 被指定了两次；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: only torque goes in a multi-motor frame; nothing was sent</source>
        <translation>驱动器 %1：多电机帧只能承载转矩；未发送任何内容</translation>
    </message>
    <message>
        <source>the multi-motor torque frame (0x280) exists on CAN only (the old CAN generation); RS485 has none; nothing was sent</source>
        <translation>多电机转矩帧（0x280）仅存在于 CAN（旧一代 CAN）；RS485 没有该帧；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: its series and CAN generation are not known (give them, e.g. --drives %1:MG@can); the multi-motor frame exists on the old generation only; nothing was sent</source>
        <translation>驱动器 %1：其系列和 CAN 代别未知（请给出，例如 --drives %1:MG@can）；多电机帧仅存在于旧一代；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1 speaks CAN V2.36, whose documents have no multi-motor torque frame (0x280 is encoded for the old generation only); nothing was sent</source>
        <translation>驱动器 %1 使用 CAN V2.36，其文档中没有多电机转矩帧（0x280 仅按旧一代编码）；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: its series is not known, so its torque cannot be bounded (give it, e.g. --drives %1:MG@can); nothing was sent</source>
        <translation>驱动器 %1：其系列未知，无法限制其转矩（请给出，例如 --drives %1:MG@can）；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: |iq| %2 A is over its series&apos; current %3 A; nothing was sent</source>
        <translation>驱动器 %1：|iq| %2 A 超过其系列电流 %3 A；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: |iq| %2 A is over its torque limit %3 A (max_torque_a); nothing was sent</source>
        <translation>驱动器 %1：|iq| %2 A 超过其转矩限制 %3 A（max_torque_a）；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: its series has no torque command; nothing was sent</source>
        <translation>驱动器 %1：其系列没有转矩命令；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1: refused by its limits; nothing was sent</source>
        <translation>驱动器 %1：被其限制拒绝；未发送任何内容</translation>
    </message>
    <message>
        <source>drive %1 is on the bus and would get 0 A from the multi-motor torque frame, which has a slot for each of IDs 1..4: name it (%1=0 for zero torque on purpose); nothing was sent</source>
        <translation>驱动器 %1 在总线上，多电机转矩帧为 ID 1..4 各留一个位置，它会收到 0 A：请写出它（%1=0 表示有意给零转矩）；未发送任何内容</translation>
    </message>
</context>
<context>
    <name>lk::safety::SoftLimits</name>
    <message>
        <source>%1 must be a whole number in %2 (got %3)</source>
        <translation>%1 必须是 %2 范围内的整数（实际为 %3）</translation>
    </message>
    <message>
        <source>%1 must be a number in %2 (got %3)</source>
        <translation>%1 必须是 %2 范围内的数值（实际为 %3）</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot; (the keys are %2)</source>
        <translation>未知的键“%1”（可用的键：%2）</translation>
    </message>
    <message>
        <source>min_angle_deg (%1) must not exceed max_angle_deg (%2)</source>
        <translation>min_angle_deg（%1）不能大于 max_angle_deg（%2）</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>不是 JSON 对象</translation>
    </message>
    <message>
        <source>not a JSON object (%1 at byte %2)</source>
        <translation>不是 JSON 对象（%1，位于第 %2 字节）</translation>
    </message>
    <message>
        <source>key &quot;%1&quot; is given twice</source>
        <translation>键“%1”出现了两次</translation>
    </message>
</context>
<context>
    <name>lk::system::AtomicFile</name>
    <message>
        <source>the file was not opened</source>
        <translation>文件未打开</translation>
    </message>
</context>
<context>
    <name>lk::system::BoundedFile</name>
    <message>
        <source>a directory</source>
        <translation>一个目录</translation>
    </message>
    <message>
        <source>a FIFO (named pipe)</source>
        <translation>一个 FIFO（命名管道）</translation>
    </message>
    <message>
        <source>a character device</source>
        <translation>一个字符设备</translation>
    </message>
    <message>
        <source>a block device</source>
        <translation>一个块设备</translation>
    </message>
    <message>
        <source>a socket</source>
        <translation>一个套接字</translation>
    </message>
    <message>
        <source>not a regular file</source>
        <translation>不是普通文件</translation>
    </message>
    <message>
        <source>it is %1, not a regular file</source>
        <translation>它是%1，不是普通文件</translation>
    </message>
    <message>
        <source>%1 bytes</source>
        <translation>%1 字节</translation>
    </message>
    <message>
        <source>it is %1, more than the %2 such a file may have</source>
        <translation>它有 %1，超过此类文件允许的 %2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 MB</source>
        <translation>%1 MB</translation>
    </message>
</context>
<context>
    <name>lk::text::CommandTitle</name>
    <message>
        <source>Read model</source>
        <translation>读取型号</translation>
    </message>
    <message>
        <source>Write the position as zero to ROM</source>
        <translation>将当前位置作为零点写入 ROM</translation>
    </message>
    <message>
        <source>Read PID gains</source>
        <translation>读取 PID 参数</translation>
    </message>
    <message>
        <source>Write PID gains to RAM</source>
        <translation>写入 PID 参数到 RAM</translation>
    </message>
    <message>
        <source>Write PID gains to ROM</source>
        <translation>写入 PID 参数到 ROM</translation>
    </message>
    <message>
        <source>Read acceleration</source>
        <translation>读取加速度</translation>
    </message>
    <message>
        <source>Write acceleration to RAM</source>
        <translation>写入加速度到 RAM</translation>
    </message>
    <message>
        <source>Read parameter</source>
        <translation>读取参数</translation>
    </message>
    <message>
        <source>Write parameter to RAM</source>
        <translation>写入参数到 RAM</translation>
    </message>
    <message>
        <source>Write parameter to ROM</source>
        <translation>写入参数到 ROM</translation>
    </message>
    <message>
        <source>Motor Off</source>
        <translation>电机关闭</translation>
    </message>
    <message>
        <source>Motor Stop</source>
        <translation>电机停止</translation>
    </message>
    <message>
        <source>Motor Run</source>
        <translation>电机运行</translation>
    </message>
    <message>
        <source>Brake control</source>
        <translation>抱闸控制</translation>
    </message>
    <message>
        <source>Read encoder</source>
        <translation>读取编码器</translation>
    </message>
    <message>
        <source>Write encoder offset to ROM</source>
        <translation>写入编码器零偏到 ROM</translation>
    </message>
    <message>
        <source>Read multi-turn angle</source>
        <translation>读取多圈角度</translation>
    </message>
    <message>
        <source>Clear turn count</source>
        <translation>清除圈数</translation>
    </message>
    <message>
        <source>Read single-turn angle</source>
        <translation>读取单圈角度</translation>
    </message>
    <message>
        <source>Clear angle</source>
        <translation>清除角度</translation>
    </message>
    <message>
        <source>Read state 1 (temperature, voltage, errors)</source>
        <translation>读取状态 1（温度、电压、错误）</translation>
    </message>
    <message>
        <source>Clear errors</source>
        <translation>清除错误</translation>
    </message>
    <message>
        <source>Read state 2 (current, speed, encoder)</source>
        <translation>读取状态 2（电流、速度、编码器）</translation>
    </message>
    <message>
        <source>Read state 3 (phase currents)</source>
        <translation>读取状态 3（相电流）</translation>
    </message>
    <message>
        <source>Open loop power</source>
        <translation>开环功率控制</translation>
    </message>
    <message>
        <source>Torque current</source>
        <translation>转矩电流控制</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度控制</translation>
    </message>
    <message>
        <source>Multi-turn position</source>
        <translation>多圈位置控制</translation>
    </message>
    <message>
        <source>Multi-turn position with speed limit</source>
        <translation>限速多圈位置控制</translation>
    </message>
    <message>
        <source>Single-turn position</source>
        <translation>单圈位置控制</translation>
    </message>
    <message>
        <source>Single-turn position with speed limit</source>
        <translation>限速单圈位置控制</translation>
    </message>
    <message>
        <source>Incremental position</source>
        <translation>增量位置控制</translation>
    </message>
    <message>
        <source>Incremental position with speed limit</source>
        <translation>限速增量位置控制</translation>
    </message>
    <message>
        <source>Read control parameter</source>
        <translation>读取控制参数</translation>
    </message>
    <message>
        <source>Write control parameter to RAM</source>
        <translation>写控制参数到 RAM</translation>
    </message>
    <message>
        <source>Multi-motor torque (0x280)</source>
        <translation>多电机转矩（0x280）</translation>
    </message>
</context>
<context>
    <name>lk::text::VerdictText</name>
    <message>
        <source>this command</source>
        <translation>此命令</translation>
    </message>
    <message>
        <source>the max speed %1 dps is over %2 dps, the top speed of the slowest series (the drive&apos;s series is unknown)</source>
        <translation>最大速度 %1 dps 超过 %2 dps，即最慢系列的最高速度（驱动的系列未知）</translation>
    </message>
    <message>
        <source>the speed %1 dps is over %2 dps, the top speed of the slowest series (the drive&apos;s series is unknown)</source>
        <translation>速度 %1 dps 超过 %2 dps，即最慢系列的最高速度（驱动的系列未知）</translation>
    </message>
    <message>
        <source>the max speed %1 dps is over the %2 series top speed of %3 dps</source>
        <translation>最大速度 %1 dps 超过 %2 系列的最高速度 %3 dps</translation>
    </message>
    <message>
        <source>the speed %1 dps is over the %2 series top speed of %3 dps</source>
        <translation>速度 %1 dps 超过 %2 系列的最高速度 %3 dps</translation>
    </message>
    <message>
        <source>no speed limit is set: set one first</source>
        <translation>未设置速度限值：请先设置</translation>
    </message>
    <message>
        <source>the max speed %1 dps is over your speed limit of %2 dps</source>
        <translation>最大速度 %1 dps 超过您的速度限值 %2 dps</translation>
    </message>
    <message>
        <source>the speed %1 dps is over your speed limit of %2 dps</source>
        <translation>速度 %1 dps 超过您的速度限值 %2 dps</translation>
    </message>
    <message>
        <source>a move of %1° from the current angle %2° is more than one output turn (%3°): move in smaller steps</source>
        <translation>从当前角度 %2° 移动 %1° 超过输出轴一圈（%3°）：请分小步移动</translation>
    </message>
    <message>
        <source>an increment of %1° is more than one output turn (%2°): move in smaller steps</source>
        <translation>增量 %1° 超过输出轴一圈（%2°）：请分小步移动</translation>
    </message>
    <message>
        <source>a move of %1° is more than one output turn (%2°): move in smaller steps</source>
        <translation>移动 %1° 超过输出轴一圈（%2°）：请分小步移动</translation>
    </message>
    <message>
        <source>pre-roll to FROM</source>
        <translation>预运行到 FROM</translation>
    </message>
    <message>
        <source>step</source>
        <translation>阶跃</translation>
    </message>
    <message>
        <source>return to FROM</source>
        <translation>返回 FROM</translation>
    </message>
    <message>
        <source>unknown series</source>
        <translation>未知系列</translation>
    </message>
    <message>
        <source>%1 needs the drive&apos;s series, whose current limits are unknown: scan the bus first</source>
        <translation>%1 需要知道驱动的系列，其电流限值未知：请先扫描总线</translation>
    </message>
    <message>
        <source>%1 drives do not implement %2</source>
        <translation>%1 驱动不支持 %2</translation>
    </message>
    <message>
        <source>the torque current %1 A is over the %2 series rating of %3 A</source>
        <translation>转矩电流 %1 A 超过 %2 系列的额定值 %3 A</translation>
    </message>
    <message>
        <source>the torque current %1 A is over your torque limit of %2 A</source>
        <translation>转矩电流 %1 A 超过您的转矩限值 %2 A</translation>
    </message>
    <message>
        <source>the open-loop power %1 is over your power limit of %2 (of 1000)</source>
        <translation>开环功率 %1 超过您的功率限值 %2（满量程 1000）</translation>
    </message>
    <message>
        <source>the target %1° is below your angle range (min %2°)</source>
        <translation>目标 %1° 低于您的角度范围（最小 %2°）</translation>
    </message>
    <message>
        <source>the target %1° is above your angle range (max %2°)</source>
        <translation>目标 %1° 高于您的角度范围（最大 %2°）</translation>
    </message>
    <message>
        <source>an increment of %1° is over your step limit of %2°</source>
        <translation>增量 %1° 超过您的步长限值 %2°</translation>
    </message>
    <message>
        <source>the drive&apos;s current angle is not known, so the move cannot be checked: read it (0x92) first</source>
        <translation>驱动的当前角度未知，无法检查此次运动：请先读取 (0x92)</translation>
    </message>
    <message>
        <source>within your speed limit of %1 dps</source>
        <translation>在您的速度限值 %1 dps 以内</translation>
    </message>
    <message>
        <source>max speed %1 dps (your speed limit)</source>
        <translation>最大速度 %1 dps（您的速度限值）</translation>
    </message>
    <message>
        <source>max speed %1 dps (the series top speed)</source>
        <translation>最大速度 %1 dps（该系列的最高速度）</translation>
    </message>
    <message>
        <source>max speed %1 dps (the max speed you gave)</source>
        <translation>最大速度 %1 dps（您给定的最大速度）</translation>
    </message>
    <message>
        <source>%1 dps</source>
        <translation>%1 dps</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 -&gt; %2 dps</source>
        <translation>%1 -&gt; %2 dps</translation>
    </message>
    <message>
        <source>%1° -&gt; %2°</source>
        <translation>%1° -&gt; %2°</translation>
    </message>
    <message>
        <source>setpoint %1 of %2 (%3, %4 at %5 s): %6</source>
        <translation>第 %1 个设定点（共 %2 个；%3，%4，于 %5 s）：%6</translation>
    </message>
    <message>
        <source>Listen-only: this tool transmits nothing. Take over the bus to send.</source>
        <translation>仅监听：本工具不发送任何内容。要发送请先接管总线。</translation>
    </message>
    <message>
        <source>Listen-only: NOTHING was sent. Stop the machine with its own emergency stop.</source>
        <translation>仅监听：什么都没有发送。请用机器自己的急停按钮停止机器。</translation>
    </message>
</context>
<context>
    <name>lk::transport::CanTransport</name>
    <message>
        <source>There is no CAN plugin &quot;%1&quot;. Qt finds: %2. On Debian the plugins come with libqt6serialbus6; peakcan also needs PEAK&apos;s PCAN-Basic library.</source>
        <translation>没有名为“%1”的 CAN 插件。Qt 找到的插件：%2。在 Debian 上这些插件随 libqt6serialbus6 一起安装；peakcan 还需要 PEAK 的 PCAN-Basic 库。</translation>
    </message>
    <message>
        <source>%1 cannot be opened (%2). `ip link show` lists the CAN interfaces; bring one up with: %3</source>
        <translation>无法打开 %1（%2）。`ip link show` 可列出 CAN 接口；用以下命令启用接口：%3</translation>
    </message>
    <message>
        <source>%1 did not take a frame (%2). The link stays open; if this repeats, check that the interface is up: %3</source>
        <translation>%1 未能接收一帧（%2）。链路保持打开；如果反复出现，请检查接口是否已启用：%3</translation>
    </message>
    <message>
        <source>%1 is bus-off: the CAN controller stopped sending after too many errors. Usual causes: a bit rate other than the drives&apos; (%2 bit/s here; LK drives default to 1000000), a missing 120 ohm terminator at an end of the bus, or CAN-H and CAN-L swapped. Fix the cause, then restart the interface: ip link set %3 down &amp;&amp; ip link set %3 type can bitrate %2 restart-ms 100 &amp;&amp; ip link set %3 up</source>
        <translation>%1 处于总线关闭（bus-off）状态：CAN 控制器因错误过多而停止发送。常见原因：比特率与驱动器不一致（此处为 %2 bit/s；LK 驱动器默认 1000000）、总线一端缺少 120 欧终端电阻，或 CAN-H 与 CAN-L 接反。排除原因后重启接口：ip link set %3 down &amp;&amp; ip link set %3 type can bitrate %2 restart-ms 100 &amp;&amp; ip link set %3 up</translation>
    </message>
    <message>
        <source>%1 is error-passive: many frames fail on the CAN bus. Check that the drives use %2 bit/s, that both ends of the bus have a 120 ohm terminator, and the wiring of CAN-H, CAN-L and ground.</source>
        <translation>%1 处于错误被动（error-passive）状态：CAN 总线上有大量帧失败。请检查驱动器是否使用 %2 bit/s、总线两端是否各有一个 120 欧终端电阻，以及 CAN-H、CAN-L 和地线的接线。</translation>
    </message>
    <message>
        <source>Nobody acknowledged a frame on %1: no drive is powered on the bus, the drives use another bit rate than %2 bit/s, or CAN-H/CAN-L are not connected. Check the drives&apos; power, the wiring and the bit rate.</source>
        <translation>%1 上的帧没有任何节点应答（ACK）：总线上没有通电的驱动器、驱动器的比特率不是 %2 bit/s，或 CAN-H/CAN-L 未接好。请检查驱动器电源、接线和比特率。</translation>
    </message>
    <message>
        <source>The bit rate of %1 could not be set through Qt (%2). If the interface already runs at %3 bit/s nothing needs doing; otherwise set it as root: %4</source>
        <translation>无法通过 Qt 设置 %1 的比特率（%2）。如果接口已在 %3 bit/s 下运行则无需处理；否则请以 root 身份设置：%4</translation>
    </message>
    <message>
        <source>The CAN interface %1 went away (%2).</source>
        <translation>CAN 接口 %1 已消失（%2）。</translation>
    </message>
</context>
<context>
    <name>lk::transport::PortErrorText</name>
    <message>
        <source>No permission to open %1. Add your user to the serial port group (`sudo usermod -aG dialout $USER` on Debian/Ubuntu, group `uucp` on Arch), then log out and in again.</source>
        <translation>没有权限打开 %1。请把您的用户加入串口用户组（Debian/Ubuntu 上执行 `sudo usermod -aG dialout $USER`，Arch 上为 `uucp` 组），然后注销并重新登录。</translation>
    </message>
    <message>
        <source>%1 is in use by another program (a terminal, another lkstudio, ModemManager?). Close it and try again; `fuser %1` shows who holds it.</source>
        <translation>%1 正被其他程序占用（终端、另一个 lkstudio、ModemManager？）。关闭该程序后重试；`fuser %1` 可查看占用者。</translation>
    </message>
    <message>
        <source>The serial adapter %1 was disconnected (unplugged or reset). Plug it back in and reconnect.</source>
        <translation>串口转换器 %1 已断开（被拔出或复位）。请重新插上并重新连接。</translation>
    </message>
    <message>
        <source>%1 refused %2 baud 8N1. Try another baud or another adapter.</source>
        <translation>%1 不接受 %2 波特 8N1。请换一个波特率或换一个转换器。</translation>
    </message>
    <message>
        <source>%1 is not a serial device. Give the adapter&apos;s port, e.g. /dev/ttyUSB0; `ls /dev/serial/by-id/` lists the adapters plugged in.</source>
        <translation>%1 不是串口设备。请指定转换器的串口，例如 /dev/ttyUSB0；`ls /dev/serial/by-id/` 会列出已插入的转换器。</translation>
    </message>
    <message>
        <source>No serial port %1. The device does not exist: is the adapter plugged in?</source>
        <translation>没有串口 %1。该设备不存在：转换器插好了吗？</translation>
    </message>
    <message>
        <source>Serial port %1 failed (input/output error). Check the cable and the adapter.</source>
        <translation>串口 %1 出错（输入/输出错误）。请检查线缆和转换器。</translation>
    </message>
</context>
<context>
    <name>lk::transport::SerialTransport</name>
    <message>
        <source>no serial ports found</source>
        <translation>未找到串口</translation>
    </message>
    <message>
        <source>ports found: %1</source>
        <translation>找到的串口：%1</translation>
    </message>
    <message>
        <source>driver set %1</source>
        <translation>驱动程序设置为 %1</translation>
    </message>
    <message>
        <source>a regular file</source>
        <translation>这是一个普通文件</translation>
    </message>
    <message>
        <source>a directory</source>
        <translation>这是一个目录</translation>
    </message>
    <message>
        <source>a pipe, socket or block device</source>
        <translation>这是管道、套接字或块设备</translation>
    </message>
    <message>
        <source>a device that is not a terminal</source>
        <translation>这是一个不是终端的设备</translation>
    </message>
</context>
<context>
    <name>lk::transport::SimTransport</name>
    <message>
        <source>Simulated bus (1 drive)</source>
        <translation>模拟总线（1 个驱动）</translation>
    </message>
    <message>
        <source>Simulated bus (%1 drives)</source>
        <translation>模拟总线（%1 个驱动）</translation>
    </message>
    <message>
        <source>The simulated bus was disconnected (fault injection). Open it again to reconnect.</source>
        <translation>模拟总线已断开（故障注入）。重新打开即可重新连接。</translation>
    </message>
    <message>
        <source>Simulated CAN bus (1 drive) @ %1 bit/s</source>
        <translation>模拟 CAN 总线（1 个驱动器）@ %1 bit/s</translation>
    </message>
    <message>
        <source>Simulated CAN bus (%1 drives) @ %2 bit/s</source>
        <translation>模拟 CAN 总线（%1 个驱动器）@ %2 bit/s</translation>
    </message>
</context>
<context>
    <name>lk::tuning::StepRunFile</name>
    <message>
        <source>Run %1 was not saved: its trace is %2, and a trace file may hold %3 (a set&apos;s traces %4 in all). Keep a shorter run.</source>
        <translation>运行 %1 未保存：其曲线有 %2，而一个曲线文件最多 %3（一组运行的曲线合计最多 %4）。请保留较短的运行。</translation>
    </message>
</context>
<context>
    <name>lk::ui::AboutDialog</name>
    <message>
        <source>About LK Servo Studio</source>
        <translation>关于 LK Servo Studio</translation>
    </message>
    <message>
        <source>&lt;h2&gt;LK Servo Studio %1&lt;/h2&gt;&lt;p&gt;Tuning and diagnostics for LK-TECH MS/MF/MG/MH servo drives on RS485 (protocols V2.3 and V2.35). Esc sends Motor Off to every drive from anywhere in the program.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;LK Servo Studio %1&lt;/h2&gt;&lt;p&gt;用于 RS485 总线上瓴控 LK-TECH MS/MF/MG/MH 伺服驱动的调参与诊断工具（协议 V2.3 与 V2.35）。在程序中任何地方按 Esc 都会向每个驱动发送电机关闭命令。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Qt %1 (built with %2), platform %3
%4
%5 (%6)</source>
        <translation>Qt %1（编译时为 %2），平台 %3
%4
%5（%6）</translation>
    </message>
    <message>
        <source>&lt;p&gt;Licence: &lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;. LK Servo Studio is free software: you may redistribute and modify it under the terms of the GNU General Public License, version 3 or any later version. It comes with ABSOLUTELY NO WARRANTY.&lt;/p&gt;</source>
        <translation>&lt;p&gt;许可证：&lt;a href=&quot;%1&quot;&gt;%2&lt;/a&gt;。LK Servo Studio 是自由软件：您可以依据 GNU 通用公共许可证第 3 版或任何更新版本的条款再发布和修改它。本程序不提供任何担保。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Copy diagnostics</source>
        <translation>复制诊断信息</translation>
    </message>
    <message>
        <source>Copy versions, port, adapter, bus statistics and recent errors to the clipboard, for a bug report</source>
        <translation>将版本、端口、适配器、总线统计和最近的错误复制到剪贴板，用于问题报告</translation>
    </message>
    <message>
        <source>Copied</source>
        <translation>已复制</translation>
    </message>
</context>
<context>
    <name>lk::ui::AppSettings</name>
    <message>
        <source>Your settings file %1 is damaged; these values were not used: %2.</source>
        <translation>您的设置文件 %1 已损坏；以下值未被使用：%2。</translation>
    </message>
    <message>
        <source>Your settings file %1 was not read (%2): lkstudio runs with default settings, and what you change now is not saved.</source>
        <translation>未读取您的设置文件 %1（%2）：lkstudio 以默认设置运行，现在所做的更改不会被保存。</translation>
    </message>
    <message>
        <source>Your settings file %1 was written by a newer lkstudio (%2 is %3; this release knows up to %4): only the values this release understands are used, and the file is not converted.</source>
        <translation>您的设置文件 %1 由较新版本的 lkstudio 写入（%2 为 %3；本版本最高只认识 %4）：只使用本版本能理解的值，文件不会被转换。</translation>
    </message>
</context>
<context>
    <name>lk::ui::BannerEntry</name>
    <message>
        <source>Hide this message</source>
        <translation>隐藏此消息</translation>
    </message>
</context>
<context>
    <name>lk::ui::BlackBoxRecorder</name>
    <message>
        <source>Nothing to save: no connection has been opened yet.</source>
        <translation>没有可保存的内容：尚未打开任何连接。</translation>
    </message>
    <message>
        <source>Cannot create the folder %1.</source>
        <translation>无法创建文件夹 %1。</translation>
    </message>
</context>
<context>
    <name>lk::ui::BodeChart</name>
    <message>
        <source>Magnitude (dB)</source>
        <translation>幅值 (dB)</translation>
    </message>
    <message>
        <source>Phase (°)</source>
        <translation>相位 (°)</translation>
    </message>
    <message>
        <source>Frequency (Hz)</source>
        <translation>频率 (Hz)</translation>
    </message>
    <message>
        <source>-3 dB bandwidth</source>
        <translation>-3 dB 带宽</translation>
    </message>
    <message>
        <source>Resolution limit</source>
        <translation>分辨极限</translation>
    </message>
    <message>
        <source>Dashed line: %1 Hz, the highest frequency %2 samples/s resolve (%3 samples a period at least). Not shown above it: %4 Hz.</source>
        <translation>虚线：%1 Hz，即 %2 次采样/秒所能分辨的最高频率（每周期至少 %3 个采样）。高于它而未显示的频率：%4 Hz。</translation>
    </message>
    <message>
        <source>-3 dB bandwidth %1 Hz (phase there %2°)</source>
        <translation>-3 dB 带宽 %1 Hz（该处相位 %2°）</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>no -3 dB bandwidth within the frequencies measured</source>
        <translation>在所测频率内没有 -3 dB 带宽</translation>
    </message>
    <message>
        <source>peak %1 dB at %2 Hz</source>
        <translation>峰值 %1 dB，位于 %2 Hz</translation>
    </message>
    <message>
        <source>no peak (too few points)</source>
        <translation>无峰值（点数太少）</translation>
    </message>
    <message>
        <source>%1: %2; %3.</source>
        <translation>%1：%2；%3。</translation>
    </message>
    <message>
        <source>No frequency response yet.</source>
        <translation>尚无频率响应。</translation>
    </message>
    <message>
        <source>%1
%2 Hz: %3 dB, %4°
Fit quality %5 (%6 samples)</source>
        <translation>%1
%2 Hz：%3 dB，%4°
拟合质量 %5（%6 个采样）</translation>
    </message>
</context>
<context>
    <name>lk::ui::BrakePanel</name>
    <message>
        <source>Brake (0x8C)</source>
        <translation>抱闸 (0x8C)</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>读取</translation>
    </message>
    <message>
        <source>0x8C with 0x10: reads the brake state, changes nothing</source>
        <translation>0x8C 附带 0x10：读取抱闸状态，不做任何更改</translation>
    </message>
    <message>
        <source>Engage</source>
        <translation>抱闸</translation>
    </message>
    <message>
        <source>0x8C 0x00: the brake is unpowered and holds the shaft</source>
        <translation>0x8C 0x00：抱闸断电并锁住轴</translation>
    </message>
    <message>
        <source>Release…</source>
        <translation>松开…</translation>
    </message>
    <message>
        <source>0x8C 0x01: the brake is powered and lets the shaft turn</source>
        <translation>0x8C 0x01：抱闸通电，轴可以转动</translation>
    </message>
    <message>
        <source>brake control</source>
        <translation>抱闸控制</translation>
    </message>
    <message>
        <source>No drive selected.</source>
        <translation>未选择驱动。</translation>
    </message>
    <message>
        <source>Brake state: not read yet.</source>
        <translation>抱闸状态：尚未读取。</translation>
    </message>
    <message>
        <source>engaged (unpowered, holding)</source>
        <translation>已抱闸（断电，锁住）</translation>
    </message>
    <message>
        <source>released (powered, the shaft is free)</source>
        <translation>已松开（通电，轴可自由转动）</translation>
    </message>
    <message>
        <source>unknown code 0x%1</source>
        <translation>未知代码 0x%1</translation>
    </message>
    <message>
        <source>Brake state: %1.</source>
        <translation>抱闸状态：%1。</translation>
    </message>
    <message>
        <source>Read the brake of drive %1: %2.</source>
        <translation>已读取驱动 %1 的抱闸：%2。</translation>
    </message>
    <message>
        <source>Release the brake</source>
        <translation>松开抱闸</translation>
    </message>
    <message>
        <source>Release the brake of drive %1?</source>
        <translation>松开驱动 %1 的抱闸？</translation>
    </message>
    <message>
        <source>The shaft is then held only by the motor. A vertical axis (or any load that gravity or a spring pulls) drops or turns as soon as the brake lets go unless the motor holds it.</source>
        <translation>之后轴只由电机保持。垂直轴（或任何受重力或弹簧拉动的负载）在抱闸松开的瞬间会下坠或转动，除非电机将其保持住。</translation>
    </message>
    <message>
        <source>Release brake</source>
        <translation>松开抱闸</translation>
    </message>
    <message>
        <source>Cancelled: the brake was not released, nothing was sent.</source>
        <translation>已取消：抱闸未松开，未发送任何命令。</translation>
    </message>
    <message>
        <source>The drive or the connection changed: nothing was sent.</source>
        <translation>驱动或连接已改变：未发送任何命令。</translation>
    </message>
    <message>
        <source>Reading whether the motor of drive %1 is on…</source>
        <translation>正在读取驱动 %1 的电机是否开启…</translation>
    </message>
    <message>
        <source>Refused: could not read whether the motor is on, so the brake was not released. Nothing sent. %1</source>
        <translation>已拒绝：无法读取电机是否开启，因此未松开抱闸。未发送任何命令。%1</translation>
    </message>
    <message>
        <source>The motor of drive %1 is OFF. Release the brake anyway?</source>
        <translation>驱动 %1 的电机处于关闭状态。仍要松开抱闸吗？</translation>
    </message>
    <message>
        <source>Whether the motor of drive %1 is on cannot be told (state code 0x%2). Release the brake anyway?</source>
        <translation>无法判断驱动 %1 的电机是否开启（状态代码 0x%2）。仍要松开抱闸吗？</translation>
    </message>
    <message>
        <source>Release the brake with the motor off</source>
        <translation>在电机关闭时松开抱闸</translation>
    </message>
    <message>
        <source>Nothing holds the shaft once the brake lets go: a vertical axis falls, a loaded axis turns freely. Support the load or turn the motor on first.</source>
        <translation>抱闸一旦松开，就没有任何东西保持轴：垂直轴会坠落，带负载的轴会自由转动。请先支撑负载或开启电机。</translation>
    </message>
    <message>
        <source>Release with the motor off</source>
        <translation>在电机关闭时松开</translation>
    </message>
    <message>
        <source>Refused: the motor is off, so the brake was not released. Nothing sent.</source>
        <translation>已拒绝：电机已关闭，因此未松开抱闸。未发送任何命令。</translation>
    </message>
    <message>
        <source>release (0x8C 0x01)</source>
        <translation>松开 (0x8C 0x01)</translation>
    </message>
    <message>
        <source>engage (0x8C 0x00)</source>
        <translation>抱闸 (0x8C 0x00)</translation>
    </message>
    <message>
        <source>Sent %1 to drive %2…</source>
        <translation>已向驱动 %2 发送%1…</translation>
    </message>
    <message>
        <source>Sent %1 to drive %2; it answered: %3.</source>
        <translation>已向驱动 %2 发送%1；驱动应答：%3。</translation>
    </message>
    <message>
        <source>Sent %1 to drive %2; %3</source>
        <translation>已向驱动 %2 发送%1；%3</translation>
    </message>
    <message>
        <source>Read back: %1.</source>
        <translation>回读：%1。</translation>
    </message>
    <message>
        <source>Reading it back failed: %1</source>
        <translation>回读失败：%1</translation>
    </message>
</context>
<context>
    <name>lk::ui::BusController</name>
    <message>
        <source>Reconnected: %1</source>
        <translation>已重新连接：%1</translation>
    </message>
    <message>
        <source>Lost the link to %1. %2 Sending is disabled and the data stays on screen; lkstudio reconnects when the adapter is back.</source>
        <translation>与 %1 的连接中断。%2 已禁止发送，数据保留在屏幕上；转换器恢复后 lkstudio 会自动重新连接。</translation>
    </message>
    <message>
        <source>Lost the link to %1. %2 Sending is disabled and the data stays on screen; press Disconnect, then Connect, once the adapter is back.</source>
        <translation>与 %1 的连接中断。%2 已禁止发送，数据保留在屏幕上；转换器恢复后请先点“断开”，再点“连接”。</translation>
    </message>
    <message>
        <source>Cannot use %1: %2</source>
        <translation>无法使用 %1：%2</translation>
    </message>
    <message>
        <source>the simulator</source>
        <translation>模拟器</translation>
    </message>
    <message>
        <source>Scan stopped: %1</source>
        <translation>扫描已停止：%1</translation>
    </message>
    <message>
        <source>No drive answered. Check the baud (or tick &quot;Try every baud&quot;), the A/B wiring, the drives&apos; supply and the 120-ohm termination.</source>
        <translation>没有驱动应答。请检查波特率（或勾选“尝试所有波特率”）、A/B 接线、驱动供电和 120 欧终端电阻。</translation>
    </message>
    <message>
        <source>ID %1 at %2 baud</source>
        <translation>ID %1，%2 波特</translation>
    </message>
    <message>
        <source>Drives answered at different bauds (%1). The port stays at %2 baud; give every drive on a bus the same baud.</source>
        <translation>驱动以不同的波特率应答（%1）。串口保持 %2 波特；同一总线上的所有驱动应使用相同的波特率。</translation>
    </message>
    <message>
        <source>Drive %1 did not confirm Clear Errors (%2).</source>
        <translation>驱动 %1 未确认清除错误标志（%2）。</translation>
    </message>
    <message>
        <source>Drive %1 still reports: %2. The cause is still there (supply voltage, temperature); fix it, then clear again.</source>
        <translation>驱动 %1 仍然报告：%2。原因仍然存在（供电电压、温度）；请排除后再清除。</translation>
    </message>
    <message>
        <source>Drive %1: errors cleared.</source>
        <translation>驱动 %1：错误标志已清除。</translation>
    </message>
    <message>
        <source>This tool is now the bus master: it transmits, polls the drives it saw and its emergency stop sends Motor Off.</source>
        <translation>本工具现在是总线主站：它会发送数据、轮询已看到的驱动器，急停会发送电机关闭。</translation>
    </message>
    <message>
        <source>No drive answered on %1. Check that the drives use %2, the CAN-H/CAN-L wiring, the drives&apos; supply and a 120-ohm terminator at each end of the bus.</source>
        <translation>%1 上没有驱动应答。请检查驱动是否使用 %2、CAN-H/CAN-L 接线、驱动供电，以及总线两端各有一个 120 欧终端电阻。</translation>
    </message>
    <message>
        <source>the simulated CAN bus</source>
        <translation>模拟 CAN 总线</translation>
    </message>
</context>
<context>
    <name>lk::ui::BusModel</name>
    <message>
        <source>Not connected: nothing can be sent.</source>
        <translation>未连接：无法发送任何内容。</translation>
    </message>
</context>
<context>
    <name>lk::ui::CommandedMotion</name>
    <message>
        <source>speed %1 dps</source>
        <translation>速度 %1 dps</translation>
    </message>
    <message>
        <source>torque %1 A</source>
        <translation>转矩 %1 A</translation>
    </message>
    <message>
        <source>open-loop power %1</source>
        <translation>开环功率 %1</translation>
    </message>
    <message>
        <source>position %1°</source>
        <translation>位置 %1°</translation>
    </message>
    <message>
        <source>single-turn position %1°</source>
        <translation>单圈位置 %1°</translation>
    </message>
    <message>
        <source>move by %1°</source>
        <translation>增量移动 %1°</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>驱动 %1</translation>
    </message>
    <message>
        <source>Drive %1 (%2 at %3)</source>
        <translation>驱动 %1（%3 时 %2）</translation>
    </message>
</context>
<context>
    <name>lk::ui::ConfirmDialog</name>
    <message>
        <source>The drive or the connection changed: nothing was sent.</source>
        <translation>驱动或连接已改变：未发送任何命令。</translation>
    </message>
    <message>
        <source>Cancelled: nothing was sent.</source>
        <translation>已取消：未发送任何命令。</translation>
    </message>
</context>
<context>
    <name>lk::ui::ConnectionBar</name>
    <message>
        <source>Serial port of the USB-RS485 adapter, or the built-in simulated bus. You can also type a device path, e.g. a pseudo-terminal from lksim.</source>
        <translation>USB-RS485 转换器的串口，或内置模拟总线。也可以输入设备路径，例如 lksim 的伪终端。</translation>
    </message>
    <message>
        <source>Baud rate set on the drives (DIP switches or the vendor&apos;s tool)</source>
        <translation>驱动上设定的波特率（拨码开关或厂家上位机）</translation>
    </message>
    <message>
        <source>Auto-reconnect</source>
        <translation>自动重连</translation>
    </message>
    <message>
        <source>Reopen the port by itself when the adapter comes back</source>
        <translation>转换器恢复后自动重新打开串口</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>串口：</translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <source>Simulator (built-in)</source>
        <translation>模拟器（内置）</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <source>Fix permission…</source>
        <translation>修复权限…</translation>
    </message>
    <message>
        <source>The port was refused: show the command that gives you access</source>
        <translation>端口被拒绝访问：显示获取访问权限的命令</translation>
    </message>
    <message>
        <source>Listen only</source>
        <translation>仅监听</translation>
    </message>
    <message>
        <source>Watch a bus that another controller runs: the port opens read-only and this tool transmits nothing, not even an emergency stop. Use an adapter with automatic direction control (see README, &quot;Diagnosing a running machine&quot;).</source>
        <translation>旁听由另一个控制器运行的总线：端口以只读方式打开，本工具不发送任何内容，连急停也不发送。请使用带自动方向控制的转换器（见 README“诊断正在运行的机器”）。</translation>
    </message>
    <message>
        <source>Take over the bus…</source>
        <translation>接管总线…</translation>
    </message>
    <message>
        <source>Reopen the port read-write and become the bus master (asks first)</source>
        <translation>以读写方式重新打开端口并成为总线主站（会先询问）</translation>
    </message>
    <message>
        <source>RS485</source>
        <translation>RS485</translation>
    </message>
    <message>
        <source>CAN</source>
        <translation>CAN</translation>
    </message>
    <message>
        <source>How the drives are wired to this computer: a USB-RS485 adapter, or a CAN adapter (candleLight/gs_usb, PCAN-USB, CANable; see README, &quot;Drives on CAN&quot;)</source>
        <translation>驱动与本机的连接方式：USB-RS485 适配器，或 CAN 适配器（candleLight/gs_usb、PCAN-USB、CANable；见 README“CAN 总线上的驱动”）</translation>
    </message>
    <message>
        <source>The Qt SerialBus plugin: socketcan for every adapter the Linux kernel knows (candleLight/gs_usb, PCAN-USB, CANable through slcand, vcan), virtualcan for tests without hardware</source>
        <translation>Qt SerialBus 插件：socketcan 用于 Linux 内核支持的所有适配器（candleLight/gs_usb、PCAN-USB、经 slcand 的 CANable、vcan），virtualcan 用于无硬件测试</translation>
    </message>
    <message>
        <source>The CAN interface the plugin reports (can0, slcan0, vcan0); `ip link show` lists them</source>
        <translation>插件报告的 CAN 接口（can0、slcan0、vcan0）；`ip link show` 可列出它们</translation>
    </message>
    <message>
        <source>The drives&apos; CAN bit rate (1 Mbit/s unless changed with the vendor&apos;s tool over RS485). lkstudio sets it on the interface where the system allows; otherwise it shows the command to run as root.</source>
        <translation>驱动的 CAN 比特率（除非已用厂商工具经 RS485 修改，否则为 1 Mbit/s）。系统允许时 lkstudio 会在接口上设置它；否则显示需以 root 运行的命令。</translation>
    </message>
    <message>
        <source>Plugin:</source>
        <translation>插件：</translation>
    </message>
    <message>
        <source>Interface:</source>
        <translation>接口：</translation>
    </message>
    <message>
        <source>Bit rate:</source>
        <translation>比特率：</translation>
    </message>
</context>
<context>
    <name>lk::ui::ControlCommandBox</name>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <source>Checked against the series and your soft limits before sending</source>
        <translation>发送前按系列限值和您的软限位检查</translation>
    </message>
    <message>
        <source>Motor Off</source>
        <translation>电机关闭</translation>
    </message>
    <message>
        <source>0x80: output off, the stored command is cleared</source>
        <translation>0x80：关闭输出，清除已保存的命令</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>电机停止</translation>
    </message>
    <message>
        <source>0x81: output off, the stored command is kept for Run</source>
        <translation>0x81：关闭输出，保留命令供“电机运行”恢复</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>电机运行</translation>
    </message>
    <message>
        <source>0x88: resume after Stop</source>
        <translation>0x88：在“电机停止”后恢复</translation>
    </message>
    <message numerus="yes">
        <source>%n drives are selected: every command here acts on %1 only.</source>
        <translation>
            <numerusform>已选择 %n 个驱动：此处的每条命令只作用于 %1。</numerusform>
        </translation>
    </message>
    <message>
        <source>Motor On</source>
        <translation>电机开启</translation>
    </message>
    <message>
        <source>0x88: turns the motor on after Motor Off or a protection trip (V2.35: a control command does not); it holds no command</source>
        <translation>0x88：在电机关闭或保护跳闸后开启电机（V2.35：控制命令不会开启电机）；不保留任何命令</translation>
    </message>
</context>
<context>
    <name>lk::ui::ControlLimits</name>
    <message>
        <source>The soft limits stored for %1 are damaged (%2); the limits in force stay. Apply them to store them again.</source>
        <translation>%1 保存的软限位已损坏（%2）；当前生效的限值保持不变。点“应用”可重新保存。</translation>
    </message>
    <message>
        <source>Refused: the soft limits stored for %1 are damaged (%2). Check and apply the limits first; nothing sent.</source>
        <translation>已拒绝：%1 保存的软限位已损坏（%2）。请先检查并应用限值；未发送任何命令。</translation>
    </message>
    <message>
        <source>Max Speed %1 dps</source>
        <translation>最大速度 %1 dps</translation>
    </message>
    <message>
        <source>max torque current %1 A</source>
        <translation>最大转矩电流 %1 A</translation>
    </message>
    <message>
        <source>Max Power %1</source>
        <translation>最大功率 %1</translation>
    </message>
    <message>
        <source>Max Angle %1°</source>
        <translation>最大角度 %1°</translation>
    </message>
    <message>
        <source>The drive&apos;s own limits (read from it) also apply where lower: %1.</source>
        <translation>驱动器自身的限制（从驱动器读取）在更低时同样生效：%1。</translation>
    </message>
</context>
<context>
    <name>lk::ui::ControlModePanel</name>
    <message>
        <source>dps (°/s)</source>
        <translation>dps (°/s)</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>rpm</translation>
    </message>
    <message>
        <source>Unit of every speed field; rotor speed, as on the wire.</source>
        <translation>所有速度字段的单位；转子速度，与通信数据一致。</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>模式：</translation>
    </message>
    <message>
        <source>Speed unit:</source>
        <translation>速度单位：</translation>
    </message>
    <message>
        <source>Open loop power (0xA0)</source>
        <translation>开环控制 (0xA0)</translation>
    </message>
    <message>
        <source>Torque current (0xA1)</source>
        <translation>转矩闭环控制 (0xA1)</translation>
    </message>
    <message>
        <source>Speed (0xA2)</source>
        <translation>速度闭环控制 (0xA2)</translation>
    </message>
    <message>
        <source>Multi-turn position (0xA3/0xA4)</source>
        <translation>多圈位置闭环控制 (0xA3/0xA4)</translation>
    </message>
    <message>
        <source>Single-turn position (0xA5/0xA6)</source>
        <translation>单圈位置闭环控制 (0xA5/0xA6)</translation>
    </message>
    <message>
        <source>Incremental position (0xA7/0xA8)</source>
        <translation>增量位置闭环控制 (0xA7/0xA8)</translation>
    </message>
    <message>
        <source>Not limited by the drive: your open-loop limit applies.</source>
        <translation>驱动不限制此值：由您的开环功率限值限制。</translation>
    </message>
    <message>
        <source> A</source>
        <translation> A</translation>
    </message>
    <message>
        <source>Torque current iq:</source>
        <translation>转矩电流 iq：</translation>
    </message>
    <message>
        <source>Not limited by the drive: your torque limit applies.</source>
        <translation>驱动不限制此值：由您的转矩限值限制。</translation>
    </message>
    <message>
        <source>Speed (sign = direction):</source>
        <translation>速度（正负号 = 方向）：</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Target angle (rotor, multi-turn):</source>
        <translation>目标角度（转子，多圈）：</translation>
    </message>
    <message>
        <source>0..359.99° within one rotor turn</source>
        <translation>转子一圈内的 0..359.99°</translation>
    </message>
    <message>
        <source>Clockwise</source>
        <translation>顺时针</translation>
    </message>
    <message>
        <source>Counter-clockwise</source>
        <translation>逆时针</translation>
    </message>
    <message>
        <source>Target angle (0..359.99):</source>
        <translation>目标角度 (0..359.99)：</translation>
    </message>
    <message>
        <source>Direction:</source>
        <translation>方向：</translation>
    </message>
    <message>
        <source>Move by (sign = direction):</source>
        <translation>移动量（正负号 = 方向）：</translation>
    </message>
    <message>
        <source> rpm</source>
        <translation> rpm</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> dps</translation>
    </message>
    <message>
        <source>Lower max speed</source>
        <translation>降低最大速度</translation>
    </message>
    <message>
        <source>Unticked, the move is sent with your speed limit as its max speed; tick to give a lower one.</source>
        <translation>不勾选时，以您的速度限值作为本次运动的最大速度发送；勾选可给定更低的值。</translation>
    </message>
    <message>
        <source>Always sent with a max speed (0xA4/0xA6/0xA8): your speed limit unless you give a lower one.</source>
        <translation>始终带最大速度发送 (0xA4/0xA6/0xA8)：默认为您的速度限值，除非您给定更低的值。</translation>
    </message>
    <message>
        <source>reading the drive&apos;s angle…</source>
        <translation>正在读取驱动角度…</translation>
    </message>
    <message>
        <source>Starts at the drive&apos;s current angle; at most one output turn away.</source>
        <translation>从驱动的当前角度开始；最多相距输出轴一圈。</translation>
    </message>
    <message>
        <source>Power (-850..850):</source>
        <translation>功率（-850..850）：</translation>
    </message>
</context>
<context>
    <name>lk::ui::ControlView</name>
    <message>
        <source>Soft limits of %1 applied and saved.</source>
        <translation>已应用并保存 %1 的软限位。</translation>
    </message>
    <message>
        <source>Stopped: the drive or the connection changed.</source>
        <translation>已停止：驱动或连接已改变。</translation>
    </message>
    <message>
        <source>Disconnected: nothing can be sent.</source>
        <translation>已断开：无法发送任何命令。</translation>
    </message>
    <message>
        <source>Not connected or no drive selected: nothing sent.</source>
        <translation>未连接或未选择驱动：未发送任何命令。</translation>
    </message>
    <message>
        <source>Sent %1 to drive %2.</source>
        <translation>已向驱动 %2 发送 %1。</translation>
    </message>
    <message>
        <source>Stopped by Motor Off.</source>
        <translation>已被电机关闭命令停止。</translation>
    </message>
    <message>
        <source>Stopped by Stop.</source>
        <translation>已被电机停止命令停止。</translation>
    </message>
    <message>
        <source>Stopped: jog took over.</source>
        <translation>已停止：点动接管了控制。</translation>
    </message>
    <message>
        <source>Jogging at %1 dps: release to stop.</source>
        <translation>正以 %1 dps 点动：松开即停止。</translation>
    </message>
    <message>
        <source>Jog released: speed 0 sent.</source>
        <translation>点动已松开：已发送速度 0。</translation>
    </message>
    <message>
        <source>Step of %1° sent.</source>
        <translation>已发送 %1° 的步进。</translation>
    </message>
    <message>
        <source>Now: %1 dps</source>
        <translation>当前：%1 dps</translation>
    </message>
    <message>
        <source>, iq %1 A</source>
        <translation>，iq %1 A</translation>
    </message>
    <message>
        <source>, power %1</source>
        <translation>，功率 %1</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s current angle before the move…</source>
        <translation>运动前正在读取驱动的当前角度…</translation>
    </message>
    <message>
        <source>Sent %1 to drive %2, %3.</source>
        <translation>已向驱动 %2 发送 %1，%3。</translation>
    </message>
    <message>
        <source>Refused: the target starts at the drive&apos;s current angle, which is being read. Nothing sent.</source>
        <translation>已拒绝：目标从驱动的当前角度开始，正在读取该角度。未发送任何命令。</translation>
    </message>
    <message>
        <source>Refused: the drive changed while its angle was read. Nothing sent.</source>
        <translation>已拒绝：读取角度期间驱动已切换。未发送任何命令。</translation>
    </message>
    <message>
        <source>Refused: could not read the drive&apos;s current angle, so nothing was sent. %1</source>
        <translation>已拒绝：无法读取驱动的当前角度，因此未发送任何命令。%1</translation>
    </message>
    <message>
        <source>Stopped: the soft limits or the series changed.</source>
        <translation>已停止：软限位或系列已更改。</translation>
    </message>
    <message>
        <source>Reading whether the motor of %1 is on before the command…</source>
        <translation>发送命令前正在读取 %1 的电机是否开启…</translation>
    </message>
</context>
<context>
    <name>lk::ui::CursorReadout</name>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>Latest</source>
        <translation>最新</translation>
    </message>
    <message>
        <source>ID %1: %2</source>
        <translation>ID %1：%2</translation>
    </message>
</context>
<context>
    <name>lk::ui::DashboardPanel</name>
    <message>
        <source>No drive selected. Connect to a bus and scan it; then pick a drive in the list on the left.</source>
        <translation>未选择驱动。请连接总线并扫描，然后在左侧列表中选择一个驱动。</translation>
    </message>
    <message>
        <source>Electrical</source>
        <translation>电气</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Supply voltage</source>
        <translation>母线电压</translation>
    </message>
    <message>
        <source>Torque current iq</source>
        <translation>转矩电流 iq</translation>
    </message>
    <message>
        <source>Phase A</source>
        <translation>A 相电流</translation>
    </message>
    <message>
        <source>Phase B</source>
        <translation>B 相电流</translation>
    </message>
    <message>
        <source>Phase C</source>
        <translation>C 相电流</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>运动</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>编码器</translation>
    </message>
    <message>
        <source>Multi-turn angle</source>
        <translation>多圈角度</translation>
    </message>
    <message>
        <source>Single-turn angle</source>
        <translation>单圈角度</translation>
    </message>
    <message>
        <source>Error flags</source>
        <translation>错误标志</translation>
    </message>
    <message>
        <source>Clear Errors</source>
        <translation>清除错误标志</translation>
    </message>
    <message>
        <source>Send clear_errors (0x9B). A drive keeps a flag while its cause (low voltage, heat) is still there.</source>
        <translation>发送 clear_errors (0x9B)。只要原因（低压、过热）仍然存在，驱动就会保留该标志。</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>驱动 %1</translation>
    </message>
    <message>
        <source>driver %1</source>
        <translation>驱动型号 %1</translation>
    </message>
    <message>
        <source>series %1</source>
        <translation>%1 系列</translation>
    </message>
    <message>
        <source>firmware %1, hardware %2</source>
        <translation>固件 %1，硬件 %2</translation>
    </message>
    <message>
        <source>Power (relative, MS)</source>
        <translation>输出功率（相对值，MS）</translation>
    </message>
    <message>
        <source>output shaft</source>
        <translation>输出轴</translation>
    </message>
    <message>
        <source>rotor</source>
        <translation>转子</translation>
    </message>
    <message>
        <source>Multi-turn angle (%1)</source>
        <translation>多圈角度（%1）</translation>
    </message>
    <message>
        <source>Single-turn angle (%1)</source>
        <translation>单圈角度（%1）</translation>
    </message>
    <message>
        <source>Speed (%1)</source>
        <translation>速度（%1）</translation>
    </message>
    <message>
        <source>Gear ratio %1:1 from the motor name: angles and speeds are shown at the output shaft; hover for rotor values.</source>
        <translation>型号名给出减速比 %1:1：角度和速度按输出轴显示；悬停可查看转子值。</translation>
    </message>
    <message>
        <source>The motor name gives no gear ratio: angles and speeds are rotor values.</source>
        <translation>型号名未给出减速比：角度和速度为转子值。</translation>
    </message>
    <message>
        <source>not on MS</source>
        <translation>MS 无此项</translation>
    </message>
    <message>
        <source>Rotor: %1</source>
        <translation>转子：%1</translation>
    </message>
    <message>
        <source>Not read yet</source>
        <translation>尚未读取</translation>
    </message>
    <message>
        <source>(no update for over a second)</source>
        <translation>（超过一秒未更新）</translation>
    </message>
    <message>
        <source>Bus current</source>
        <translation>母线电流</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>电机</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>Shown red from %1 °C</source>
        <translation>自 %1 °C 起显示为红色</translation>
    </message>
    <message>
        <source>Shown red outside %1</source>
        <translation>超出 %1 时显示为红色</translation>
    </message>
    <message>
        <source>Torque current or power (series unknown)</source>
        <translation>转矩电流或功率（系列未知）</translation>
    </message>
    <message>
        <source>No model reply told this drive&apos;s series: an MS drive reports power here, the others current. Choose the series in the Bus panel.</source>
        <translation>没有型号应答告知此驱动器的系列：MS 驱动器在此报告功率，其他系列报告电流。请在总线面板中选择系列。</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveFaultWatch</name>
    <message>
        <source>fault flags %1</source>
        <translation>故障标志 %1</translation>
    </message>
    <message>
        <source>fault flags clear</source>
        <translation>故障标志已清除</translation>
    </message>
    <message>
        <source>supply %1 outside the series&apos; range (%2)</source>
        <translation>供电 %1 超出该系列的范围（%2）</translation>
    </message>
    <message>
        <source>supply back in range (%1)</source>
        <translation>供电已回到范围内（%1）</translation>
    </message>
    <message>
        <source>stopped by itself: %1</source>
        <translation>自行停止：%1</translation>
    </message>
    <message>
        <source>Drive %1 stopped by itself at %2: %3. It no longer follows %4.</source>
        <translation>驱动器 %1 于 %2 自行停止：%3。它不再执行 %4。</translation>
    </message>
    <message>
        <source>it reads motor off</source>
        <translation>读数显示电机已关闭</translation>
    </message>
    <message>
        <source>it reads 0 dps under a speed command</source>
        <translation>在速度指令下读数为 0 dps</translation>
    </message>
    <message>
        <source>it reads no current under a torque command</source>
        <translation>在转矩指令下读数无电流</translation>
    </message>
    <message>
        <source>it reads no power under an open-loop command</source>
        <translation>在开环指令下读数无功率</translation>
    </message>
    <message>
        <source>stopped by itself: %1 (last command %2)</source>
        <translation>自行停止：%1（最后指令 %2）</translation>
    </message>
    <message>
        <source>values in range</source>
        <translation>数值在范围内</translation>
    </message>
    <message>
        <source>Drive %1: %2.</source>
        <translation>驱动器 %1：%2。</translation>
    </message>
    <message>
        <source>Seen:</source>
        <translation>记录：</translation>
    </message>
    <message>
        <source>temperature %1 °C (hot from %2 °C)</source>
        <translation>温度 %1 °C（%2 °C 起为过热）</translation>
    </message>
    <message>
        <source>temperature back below %1 °C (%2 °C)</source>
        <translation>温度已回落到 %1 °C 以下（%2 °C）</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveHealth</name>
    <message>
        <source>%1: %2-%3 V</source>
        <translation>%1：%2-%3 V</translation>
    </message>
    <message>
        <source>fault flags %1 (0x%2)</source>
        <translation>故障标志 %1（0x%2）</translation>
    </message>
    <message>
        <source>supply %1, below the series&apos; range (%2)</source>
        <translation>供电 %1，低于该系列的范围（%2）</translation>
    </message>
    <message>
        <source>supply %1, above the series&apos; range (%2)</source>
        <translation>供电 %1，高于该系列的范围（%2）</translation>
    </message>
    <message>
        <source>temperature %1 (hot from %2 °C)</source>
        <translation>温度 %1（%2 °C 起为过热）</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveInfoView</name>
    <message>
        <source>This drive</source>
        <translation>当前驱动</translation>
    </message>
    <message>
        <source>Read again</source>
        <translation>重新读取</translation>
    </message>
    <message>
        <source>Copy to clipboard</source>
        <translation>复制到剪贴板</translation>
    </message>
    <message>
        <source>Bus report</source>
        <translation>总线报告</translation>
    </message>
    <message>
        <source>Bus report…</source>
        <translation>总线报告…</translation>
    </message>
    <message>
        <source>Every known drive: ID, model, versions, PID, acceleration and state, saved as JSON and as a readable HTML page</source>
        <translation>所有已知驱动：ID、型号、版本、PID、加速度和状态，保存为 JSON 和可阅读的 HTML 页面</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>电机</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>PID (angle · speed · iq)</source>
        <translation>PID（角度 · 速度 · iq）</translation>
    </message>
    <message>
        <source>Accel (dps/s)</source>
        <translation>加速度 (dps/s)</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>Model read from drive %1.</source>
        <translation>已从驱动 %1 读取型号。</translation>
    </message>
    <message>
        <source>No drive selected.</source>
        <translation>未选择驱动。</translation>
    </message>
    <message>
        <source>Driver name</source>
        <translation>驱动名称</translation>
    </message>
    <message>
        <source>Motor name</source>
        <translation>电机名称</translation>
    </message>
    <message>
        <source>Hardware version</source>
        <translation>硬件版本</translation>
    </message>
    <message>
        <source>Firmware version</source>
        <translation>固件版本</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>协议</translation>
    </message>
    <message>
        <source>Gear ratio (from the name)</source>
        <translation>减速比（取自型号名）</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Encoder (from the name)</source>
        <translation>编码器（取自型号名）</translation>
    </message>
    <message>
        <source>%1-bit</source>
        <translation>%1 位</translation>
    </message>
    <message>
        <source>not in the name</source>
        <translation>型号名中没有</translation>
    </message>
    <message>
        <source>Drive ID: %1</source>
        <translation>驱动 ID：%1</translation>
    </message>
    <message>
        <source>Series: %1</source>
        <translation>系列：%1</translation>
    </message>
    <message>
        <source>Driver name: %1</source>
        <translation>驱动名称：%1</translation>
    </message>
    <message>
        <source>Motor name: %1</source>
        <translation>电机名称：%1</translation>
    </message>
    <message>
        <source>Hardware version: %1</source>
        <translation>硬件版本：%1</translation>
    </message>
    <message>
        <source>Firmware version: %1</source>
        <translation>固件版本：%1</translation>
    </message>
    <message>
        <source>Model: not read</source>
        <translation>型号：未读取</translation>
    </message>
    <message>
        <source>Copied to the clipboard.</source>
        <translation>已复制到剪贴板。</translation>
    </message>
    <message>
        <source>Connect to a bus first.</source>
        <translation>请先连接总线。</translation>
    </message>
    <message>
        <source>Gathering the bus report…</source>
        <translation>正在收集总线报告…</translation>
    </message>
    <message>
        <source>No drive is known on this bus: scan first.</source>
        <translation>此总线上没有已知的驱动：请先扫描。</translation>
    </message>
    <message>
        <source>, low voltage</source>
        <translation>，低压保护</translation>
    </message>
    <message>
        <source>, over temperature</source>
        <translation>，过温保护</translation>
    </message>
    <message>
        <source>Save bus report</source>
        <translation>保存总线报告</translation>
    </message>
    <message>
        <source>Bus report (*.json)</source>
        <translation>总线报告 (*.json)</translation>
    </message>
    <message>
        <source>No report gathered yet.</source>
        <translation>尚未收集报告。</translation>
    </message>
    <message>
        <source>Bus report saved: %1 and %2.</source>
        <translation>总线报告已保存：%1 和 %2。</translation>
    </message>
    <message>
        <source>Could not save the bus report: %1</source>
        <translation>无法保存总线报告：%1</translation>
    </message>
    <message>
        <source>%1 °C, %2 V</source>
        <translation>%1 °C，%2 V</translation>
    </message>
    <message numerus="yes">
        <source>Bus report gathered: %n drive(s).</source>
        <translation>
            <numerusform>已收集总线报告：%n 个驱动。</numerusform>
        </translation>
    </message>
    <message>
        <source>Motor version</source>
        <translation>电机版本</translation>
    </message>
    <message>
        <source>Unique ID</source>
        <translation>唯一 ID</translation>
    </message>
    <message>
        <source>Protocol: %1</source>
        <translation>协议：%1</translation>
    </message>
    <message>
        <source>Motor version: %1</source>
        <translation>电机版本：%1</translation>
    </message>
    <message>
        <source>Unique ID: %1</source>
        <translation>唯一 ID：%1</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveLimitSet</name>
    <message>
        <source>On MS drives ParamID 0x99 limits power (0..1000 is the power command&apos;s range); the unit is not documented.</source>
        <translation>在 MS 驱动上，参数 ID 0x99 限制的是功率（功率命令的范围为 0..1000）；单位未见文档说明。</translation>
    </message>
    <message>
        <source>In iq command units: 2048 is full scale (MF 16.5 A, MG 33 A on V2.35).</source>
        <translation>以 iq 命令单位表示：2048 为满量程（V2.35 下 MF 为 16.5 A，MG 为 33 A）。</translation>
    </message>
    <message>
        <source>Max speed (0x9A)</source>
        <translation>最大速度 (0x9A)</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> dps</translation>
    </message>
    <message>
        <source>Bounds speed and position commands (0xA2..0xA8); 0.01 dps on the wire.</source>
        <translation>限制速度与位置命令（0xA2..0xA8）；线上单位为 0.01 dps。</translation>
    </message>
    <message>
        <source>Max angle (0x9B/0x9C)</source>
        <translation>最大角度 (0x9B/0x9C)</translation>
    </message>
    <message>
        <source> deg</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Bounds multi-turn position commands (0xA3/0xA4); an int64 of 0.01 deg split over two ParamIDs, always written and read as a pair.</source>
        <translation>限制多圈位置命令（0xA3/0xA4）；一个以 0.01° 为单位的 int64，拆分在两个 参数 ID 中，总是成对写入和读取。</translation>
    </message>
    <message>
        <source>Current ramp (0x9D)</source>
        <translation>电流斜坡 (0x9D)</translation>
    </message>
    <message>
        <source>0..32767; the vendor does not document the unit.</source>
        <translation>0..32767；厂商未说明单位。</translation>
    </message>
    <message>
        <source>Speed ramp (0x9E)</source>
        <translation>速度斜坡 (0x9E)</translation>
    </message>
    <message>
        <source> dps/s</source>
        <translation> dps/s</translation>
    </message>
    <message>
        <source>Replaces the acceleration (0x33/0x34) of protocol V2.3.</source>
        <translation>取代协议 V2.3 的加速度（0x33/0x34）。</translation>
    </message>
    <message>
        <source>Drive limits (protocol V2.35)</source>
        <translation>驱动限值（协议 V2.35）</translation>
    </message>
    <message>
        <source>The drive enforces these limits itself, also against commands from other software; the tool&apos;s soft limits (Control view) only bound what this tool sends.</source>
        <translation>这些限值由驱动自身执行，对其他软件发出的命令同样有效；本工具的软限位（控制视图）只限制本工具发送的命令。</translation>
    </message>
    <message>
        <source>read_param (0x40) for 0x99..0x9E</source>
        <translation>对 0x99..0x9E 执行 read_param (0x40)</translation>
    </message>
    <message>
        <source>0x42 for each changed limit, lost at power-off; read back.</source>
        <translation>对每个已修改的限值发送 0x42，断电丢失；随后回读。</translation>
    </message>
    <message>
        <source>0x44 for every limit, writes flash (asks first); read back.</source>
        <translation>对每个限值发送 0x44，写入闪存（会先询问）；随后回读。</translation>
    </message>
    <message>
        <source>Write drive limits to ROM</source>
        <translation>将驱动限值写入 ROM</translation>
    </message>
    <message>
        <source>Write these limits to the ROM of drive %1?
%2</source>
        <translation>将这些限值写入驱动 %1 的 ROM？
%2</translation>
    </message>
    <message>
        <source>ROM is the drive&apos;s flash memory: each write wears it, and the limits stay after power-off and bound every program that drives this motor. Each parameter is sent once with 0x44 (never retried), then read back with 0x40.</source>
        <translation>ROM 是驱动的闪存：每次写入都会造成磨损，且限值在断电后仍然保留，并约束所有驱动此电机的程序。每个参数用 0x44 只发送一次（绝不重试），然后用 0x40 回读。</translation>
    </message>
    <message>
        <source>Write to ROM</source>
        <translation>写入 ROM</translation>
    </message>
    <message>
        <source>Limits written to the ROM of drive %1 and read back: the drive holds what was sent.</source>
        <translation>限值已写入驱动 %1 的 ROM 并回读：驱动保存的就是发送的值。</translation>
    </message>
    <message>
        <source>Limits written to the RAM of drive %1 and read back: the drive holds what was sent. Lost at power-off unless written to ROM.</source>
        <translation>限值已写入驱动 %1 的 RAM 并回读：驱动保存的就是发送的值。除非写入 ROM，否则断电丢失。</translation>
    </message>
    <message>
        <source>%1 (0x99)</source>
        <translation>%1 (0x99)</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveLimitsView</name>
    <message>
        <source>This drive speaks protocol V2.3: these settings do not exist in its protocol generation (they came with V2.35, ParamIDs 0x99..0x9E).</source>
        <translation>此驱动使用协议 V2.3：这些设置在该协议版本中不存在（它们随 V2.35 引入，参数 ID 0x99..0x9E）。</translation>
    </message>
    <message>
        <source>Read limits</source>
        <translation>读取限值</translation>
    </message>
    <message>
        <source>Write limits to RAM</source>
        <translation>将限值写入 RAM</translation>
    </message>
    <message>
        <source>Write limits to ROM…</source>
        <translation>将限值写入 ROM…</translation>
    </message>
    <message>
        <source>The write failed: %1</source>
        <translation>写入失败：%1</translation>
    </message>
    <message>
        <source>Written, but the read-back differs (below).</source>
        <translation>已写入，但回读值不同（见下方）。</translation>
    </message>
    <message>
        <source>Could not read the limits of drive %1: %2 Editing and writing stay off until every limit has been read.</source>
        <translation>无法读取驱动 %1 的限值：%2 在所有限值读取成功之前，编辑和写入保持禁用。</translation>
    </message>
    <message>
        <source>Limits read from drive %1 at %2.</source>
        <translation>已于 %2 从驱动 %1 读取限值。</translation>
    </message>
    <message>
        <source>Nothing was sent: the drive&apos;s limits have not all been read on this connection. Read limits first.</source>
        <translation>未发送任何命令：本次连接中尚未读取驱动的全部限值。请先读取限值。</translation>
    </message>
    <message>
        <source>ROM write cancelled: nothing was sent.</source>
        <translation>已取消 ROM 写入：未发送任何命令。</translation>
    </message>
    <message>
        <source>The drive or the connection changed: nothing was sent.</source>
        <translation>驱动或连接已改变：未发送任何命令。</translation>
    </message>
    <message>
        <source>Nothing was sent: %1</source>
        <translation>未发送任何命令：%1</translation>
    </message>
    <message>
        <source>Writing limits to the ROM of drive %1…</source>
        <translation>正在将限值写入驱动 %1 的 ROM…</translation>
    </message>
    <message>
        <source>Writing limits to the RAM of drive %1…</source>
        <translation>正在将限值写入驱动 %1 的 RAM…</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveStateCheck</name>
    <message>
        <source>Refused: whether the motor of drive %1 is on could not be told (read_state1). Nothing sent.</source>
        <translation>已拒绝：无法确定驱动器 %1 的电机是否开启（read_state1）。未发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: drive %1 is off: Motor On first (a V2.35 drive stays off after Motor Off or a protection trip, and a control command does not turn it on). Nothing sent.</source>
        <translation>已拒绝：驱动器 %1 处于关闭状态：请先开启电机（V2.35 驱动器在电机关闭或保护跳闸后保持关闭，控制命令不会开启它）。未发送任何内容。</translation>
    </message>
    <message>
        <source>The brake of drive %1 reads engaged: the shaft is held and does not move until the brake is released.</source>
        <translation>驱动器 %1 的抱闸读数为已抱闸：轴被锁住，松开抱闸前不会转动。</translation>
    </message>
    <message>
        <source>motor state not read yet</source>
        <translation>尚未读取电机状态</translation>
    </message>
    <message>
        <source>motor on</source>
        <translation>电机运行</translation>
    </message>
    <message>
        <source>motor OFF: Motor On first</source>
        <translation>电机关闭：请先开启电机</translation>
    </message>
    <message>
        <source>brake not read</source>
        <translation>尚未读取抱闸</translation>
    </message>
    <message>
        <source>brake released</source>
        <translation>抱闸已释放</translation>
    </message>
    <message>
        <source>brake ENGAGED: the shaft is held</source>
        <translation>抱闸已抱紧：轴被锁住</translation>
    </message>
    <message>
        <source>Drive %1: %2; %3.</source>
        <translation>驱动器 %1：%2；%3。</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveText</name>
    <message>
        <source>%1: drive %2 did not answer.</source>
        <translation>%1：驱动 %2 无应答。</translation>
    </message>
    <message>
        <source>%1: the bus is not connected.</source>
        <translation>%1：总线未连接。</translation>
    </message>
    <message>
        <source>%1: cancelled (emergency stop or disconnect).</source>
        <translation>%1：已取消（急停或断开）。</translation>
    </message>
    <message>
        <source>%1: the reply was corrupt (%2).</source>
        <translation>%1：回复数据损坏（%2）。</translation>
    </message>
    <message>
        <source>Refused, nothing sent: %1.</source>
        <translation>已拒绝，未发送：%1。</translation>
    </message>
    <message>
        <source>Stopped by the user.</source>
        <translation>已被用户停止。</translation>
    </message>
    <message>
        <source>Stopped: another waveform started.</source>
        <translation>已停止：另一个波形已启动。</translation>
    </message>
    <message>
        <source>Stopped by the emergency stop.</source>
        <translation>已被急停停止。</translation>
    </message>
    <message>
        <source>Stopped: the bus cancelled motion commands (emergency stop).</source>
        <translation>已停止：总线取消了运动命令（急停）。</translation>
    </message>
    <message>
        <source>Stopped: the connection was lost.</source>
        <translation>已停止：连接已断开。</translation>
    </message>
    <message>
        <source>Stopped: the bus was closed.</source>
        <translation>已停止：总线已关闭。</translation>
    </message>
    <message>
        <source>Stopped: the port was reopened at another baud.</source>
        <translation>已停止：端口已以另一波特率重新打开。</translation>
    </message>
    <message>
        <source>Refused: %1.</source>
        <translation>已拒绝：%1。</translation>
    </message>
    <message>
        <source>Refused: a setpoint broke a limit.</source>
        <translation>已拒绝：某个设定点超出限位。</translation>
    </message>
    <message>
        <source>It was sent, so drive %1 may have acted on it and may be moving: check it, or stop it.</source>
        <translation>该命令已发送，驱动器 %1 可能已执行并可能正在运动：请检查或停止它。</translation>
    </message>
    <message>
        <source>Stopped: the drive went past its speed limit; the speed watch sent Motor Stop.</source>
        <translation>已停止：驱动器超过了速度限制；速度监视已发送电机停止。</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveTree</name>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>FW</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>HW</source>
        <translation>硬件</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Temp.</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>No bus</source>
        <translation>无总线</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s)</source>
        <translation>
            <numerusform>%n 个驱动</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveView</name>
    <message>
        <source>No drive selected</source>
        <translation>未选择驱动</translation>
    </message>
    <message>
        <source>Drive %1 (%2)</source>
        <translation>驱动 %1（%2）</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>驱动 %1</translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveViews</name>
    <message>
        <source>The bus is not connected.</source>
        <translation>总线未连接。</translation>
    </message>
</context>
<context>
    <name>lk::ui::EmergencyStopButton</name>
    <message>
        <source>EMERGENCY STOP (Esc)</source>
        <translation>急停 (Esc)</translation>
    </message>
    <message>
        <source>Motor Off (0x80) to every drive on the bus, ahead of everything queued. Esc does the same from anywhere in lkstudio.</source>
        <translation>抢在所有排队命令之前，向总线上的每个驱动发送电机关闭命令 (0x80)。在 lkstudio 中任何地方按 Esc 效果相同。</translation>
    </message>
</context>
<context>
    <name>lk::ui::EmergencyStopControl</name>
    <message>
        <source>Emergency stop.</source>
        <translation>急停。</translation>
    </message>
</context>
<context>
    <name>lk::ui::EmergencyStopReport</name>
    <message>
        <source>Emergency stop: NOTHING could be sent, the bus is not connected. lkstudio has not commanded any drive to move.</source>
        <translation>急停：总线未连接，任何命令都无法发送。lkstudio 没有命令任何驱动运动。</translation>
    </message>
    <message>
        <source>Emergency stop: NOTHING could be sent, the bus is not connected. Last commanded to move: %1. They may still be moving: cut their power if needed.</source>
        <translation>急停：总线未连接，任何命令都无法发送。最后被命令运动的：%1。它们可能仍在运动：必要时请切断其电源。</translation>
    </message>
    <message numerus="yes">
        <source>Emergency stop: Motor Off sent to %n ID(s); no drive answered.</source>
        <translation>
            <numerusform>急停：已向 %n 个 ID 发送电机关闭命令；没有驱动应答。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Emergency stop: Motor Off sent to %n ID(s); acknowledged by drive(s) %1.</source>
        <translation>
            <numerusform>急停：已向 %n 个 ID 发送电机关闭命令；驱动 %1 已确认。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 could not be sent: the link dropped.</source>
        <translation>%2 个中有 %1 个无法发送：链路已断开。</translation>
    </message>
    <message>
        <source>Motor Off NEVER reached drive(s) %1: they may still be moving, cut their power if needed.</source>
        <translation>电机关闭命令从未到达驱动 %1：它们可能仍在运动，必要时请切断其电源。</translation>
    </message>
    <message>
        <source>NO answer from drive(s) %1: check them and cut their power if needed.</source>
        <translation>驱动 %1 无应答：请检查这些驱动，必要时切断其电源。</translation>
    </message>
    <message>
        <source>Pressed at %1 while the bus was not connected; sent as soon as it was back.</source>
        <translation>于 %1 在总线未连接时按下；总线恢复后已立即发送。</translation>
    </message>
    <message>
        <source>Emergency stop: Motor Off going out to every ID 1-32 (%1 of %2 done).</source>
        <translation>急停：正在向 ID 1-32 逐一发送电机关闭（已完成 %1/%2）。</translation>
    </message>
    <message>
        <source>Acknowledged so far by drive(s) %1.</source>
        <translation>目前已确认的驱动器：%1。</translation>
    </message>
    <message>
        <source>Waiting for drive(s) %1.</source>
        <translation>正在等待驱动器 %1。</translation>
    </message>
    <message>
        <source>Motor Off goes out to every drive as soon as this port is connected again (dismiss this message to cancel that).</source>
        <translation>此端口重新连接后将立即向所有驱动器发送电机关闭（关闭此消息即可取消）。</translation>
    </message>
    <message>
        <source>Drive(s) %1 did not answer but have since read stopped.</source>
        <translation>驱动器 %1 未应答，但此后读取显示已停止。</translation>
    </message>
</context>
<context>
    <name>lk::ui::EncoderLiveBox</name>
    <message>
        <source>Live (read while this view is shown)</source>
        <translation>实时（显示此页时读取）</translation>
    </message>
    <message>
        <source>Encoder (raw − offset):</source>
        <translation>编码器（原始位置 − 零偏）：</translation>
    </message>
    <message>
        <source>Raw encoder:</source>
        <translation>编码器原始位置：</translation>
    </message>
    <message>
        <source>Encoder offset:</source>
        <translation>编码器零偏：</translation>
    </message>
    <message>
        <source>Multi-turn angle (rotor):</source>
        <translation>多圈角度（转子）：</translation>
    </message>
    <message>
        <source>Output shaft:</source>
        <translation>输出轴：</translation>
    </message>
    <message>
        <source>Single-turn angle:</source>
        <translation>单圈角度：</translation>
    </message>
    <message>
        <source>Dial: the blue needle is the raw position, the red mark the offset (where the encoder reads 0); the centre shows the encoder angle.</source>
        <translation>表盘：蓝色指针为原始位置，红色标记为零偏（编码器读数为 0 处）；中央显示编码器角度。</translation>
    </message>
    <message>
        <source>%1  (%2°)</source>
        <translation>%1  (%2°)</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 (÷ %2)</source>
        <translation>%1 (÷ %2)</translation>
    </message>
    <message>
        <source>%1  (no angle: the single-turn angle disagrees, so the resolution is not known yet)</source>
        <translation>%1  （不显示角度：与单圈角度不一致，分辨率尚不确定）</translation>
    </message>
</context>
<context>
    <name>lk::ui::EncoderResolutions</name>
    <message>
        <source>%1-bit, from the model name</source>
        <translation>%1 位，取自型号名</translation>
    </message>
    <message>
        <source>%1-bit, series default</source>
        <translation>%1 位，系列默认值</translation>
    </message>
    <message>
        <source>%1-bit, a guess</source>
        <translation>%1 位，推测值</translation>
    </message>
    <message>
        <source>%1-bit, from data</source>
        <translation>%1 位，取自数据</translation>
    </message>
    <message>
        <source>%1-bit, your setting</source>
        <translation>%1 位，您的设置</translation>
    </message>
    <message>
        <source>%1 of %2 (%3)</source>
        <translation>%1 / %2（%3）</translation>
    </message>
    <message>
        <source>from the model name &quot;%1&quot;</source>
        <translation>取自型号名“%1”</translation>
    </message>
    <message>
        <source>the %1 series default</source>
        <translation>%1 系列的默认值</translation>
    </message>
    <message>
        <source>a guess: the model does not say</source>
        <translation>推测值：型号名中没有说明</translation>
    </message>
    <message>
        <source>from data: the drive reported %1, beyond the range assumed before</source>
        <translation>取自数据：驱动报告了 %1，超出了此前假定的范围</translation>
    </message>
    <message>
        <source>your setting for this drive</source>
        <translation>您为此驱动设置的值</translation>
    </message>
    <message>
        <source>but the drive reported %1, beyond this range</source>
        <translation>但驱动报告了 %1，超出了此范围</translation>
    </message>
    <message>
        <source>%1-bit, protocol V2.35</source>
        <translation>%1 位，协议 V2.35</translation>
    </message>
    <message>
        <source>what protocol V2.35 documents for %1 drives (a real MS4015 on firmware 2.35 reports 16 bits)</source>
        <translation>协议 V2.35 对 %1 驱动器的说明（固件 2.35 的真实 MS4015 报告 16 位）</translation>
    </message>
</context>
<context>
    <name>lk::ui::EncoderView</name>
    <message>
        <source>What was done (this session)</source>
        <translation>已执行的操作（本次会话）</translation>
    </message>
    <message>
        <source>Offset writes, angle clears and zero writes appear here.</source>
        <translation>零偏写入、角度清零和零点写入会显示在这里。</translation>
    </message>
    <message>
        <source>Encoder and gearbox</source>
        <translation>编码器和减速器</translation>
    </message>
    <message>
        <source>%1-bit</source>
        <translation>%1 位</translation>
    </message>
    <message>
        <source>Resolution:</source>
        <translation>分辨率：</translation>
    </message>
    <message>
        <source>Gear ratio:</source>
        <translation>减速比：</translation>
    </message>
    <message>
        <source>Encoder offset (0x91)</source>
        <translation>编码器零偏 (0x91)</translation>
    </message>
    <message>
        <source>Use current raw</source>
        <translation>使用当前原始位置</translation>
    </message>
    <message>
        <source>The present raw position becomes encoder 0</source>
        <translation>当前原始位置成为编码器 0</translation>
    </message>
    <message>
        <source>Write offset…</source>
        <translation>写入零偏…</translation>
    </message>
    <message>
        <source>The offset is the raw position that reads as encoder 0. The spec&apos;s command table calls 0x91 a ROM write: it may write the drive&apos;s flash.</source>
        <translation>零偏是编码器读数为 0 时的原始位置。协议命令表将 0x91 列为 ROM 写入：它可能会写入驱动的闪存。</translation>
    </message>
    <message>
        <source>from the model name &quot;%1&quot;</source>
        <translation>取自型号名“%1”</translation>
    </message>
    <message>
        <source>no gearbox in the model name</source>
        <translation>型号名中没有减速器</translation>
    </message>
    <message>
        <source>your setting for this drive</source>
        <translation>您为此驱动设置的值</translation>
    </message>
    <message>
        <source>Disconnected: the values shown are the last ones read.</source>
        <translation>已断开：显示的是最后读取的数值。</translation>
    </message>
    <message>
        <source>%1 counts per turn on the wire; %2.</source>
        <translation>通信数据中每圈 %1 个计数；%2。</translation>
    </message>
    <message>
        <source>Output shaft = rotor ÷ ratio; %1.</source>
        <translation>输出轴 = 转子 ÷ 减速比；%1。</translation>
    </message>
    <message>
        <source>Refused, nothing sent: the offset must be in 0..%1 for a %2-bit encoder.</source>
        <translation>已拒绝，未发送：%2 位编码器的零偏必须在 0..%1 范围内。</translation>
    </message>
    <message>
        <source>Write encoder offset</source>
        <translation>写入编码器零偏</translation>
    </message>
    <message>
        <source>Write encoder offset %1 to drive %2?</source>
        <translation>将编码器零偏 %1 写入驱动 %2？</translation>
    </message>
    <message>
        <source>The zero of the encoder and of every angle moves, so position commands go elsewhere afterwards. The spec&apos;s command table calls 0x91 a ROM write: it may wear the drive&apos;s flash.</source>
        <translation>编码器和所有角度的零点都会移动，之后的位置命令会走到别的位置。协议命令表将 0x91 列为 ROM 写入：它可能会磨损驱动的闪存。</translation>
    </message>
    <message>
        <source>Write offset</source>
        <translation>写入零偏</translation>
    </message>
    <message>
        <source>Encoder offset %1 written and read back.</source>
        <translation>编码器零偏 %1 已写入并回读。</translation>
    </message>
    <message>
        <source>Wrote offset %1, but the drive reports %2.</source>
        <translation>已写入零偏 %1，但驱动报告为 %2。</translation>
    </message>
    <message>
        <source>encoder offset</source>
        <translation>编码器偏移</translation>
    </message>
</context>
<context>
    <name>lk::ui::EncoderZeroTools</name>
    <message>
        <source>Zero</source>
        <translation>零点</translation>
    </message>
    <message>
        <source>Clear motor angle (0x95)…</source>
        <translation>清除电机角度 (0x95)…</translation>
    </message>
    <message>
        <source>Write current position to ROM as zero (0x19)…</source>
        <translation>写入当前位置到 ROM 作为零点 (0x19)…</translation>
    </message>
    <message>
        <source>Multi-turn and single-turn angle become 0 here until power-off; the result is checked with read_multi_turn (0x92).</source>
        <translation>多圈角度和单圈角度在此处变为 0，直到断电；结果用 read_multi_turn (0x92) 检查。</translation>
    </message>
    <message>
        <source>Stores the present encoder position as the zero in flash. Takes effect only after a power cycle; each write wears the flash.</source>
        <translation>将当前编码器位置作为零点存入闪存。断电重启后才生效；每次写入都会磨损闪存。</translation>
    </message>
    <message>
        <source>Clear turn count (0x93)…</source>
        <translation>清除圈数 (0x93)…</translation>
    </message>
    <message>
        <source>clear turn count</source>
        <translation>清除圈数</translation>
    </message>
    <message>
        <source>Whole turns of the multi-turn angle are dropped; the angle within the present turn stays. Checked with read_multi_turn (0x92).</source>
        <translation>多圈角度中的整圈被清除；当前圈内的角度保持不变。用 read_multi_turn (0x92) 检查。</translation>
    </message>
    <message>
        <source>Clear motor angle</source>
        <translation>清除电机角度</translation>
    </message>
    <message>
        <source>Make the present position of drive %1 angle 0?</source>
        <translation>把驱动 %1 的当前位置设为角度 0？</translation>
    </message>
    <message>
        <source>Multi-turn and single-turn angles restart from 0 here until power-off, so absolute position commands go elsewhere afterwards.</source>
        <translation>多圈和单圈角度从此处重新从 0 开始，直到断电，因此之后的绝对位置命令会走到别的位置。</translation>
    </message>
    <message>
        <source>Clear angle</source>
        <translation>清除角度</translation>
    </message>
    <message>
        <source>Clearing the angle of drive %1…</source>
        <translation>正在清除驱动 %1 的角度…</translation>
    </message>
    <message>
        <source>Angle cleared: the drive reads %1° (was %2°).</source>
        <translation>角度已清除：驱动读数为 %1°（原为 %2°）。</translation>
    </message>
    <message>
        <source>The angle read %1° before already: whether the drive applied 0x95 cannot be told.</source>
        <translation>清除前角度已经是 %1°：无法判断驱动是否执行了 0x95。</translation>
    </message>
    <message>
        <source>The drive acknowledged 0x95 but its angle did not change (%1°): this firmware ignores clear-angle. Use the encoder offset or 0x19 instead.</source>
        <translation>驱动确认了 0x95，但角度没有变化（%1°）：此固件忽略清除角度命令。请改用编码器零偏或 0x19。</translation>
    </message>
    <message>
        <source>The angle changed from %1° to %2° but is not 0: was the motor turning? Stop it and clear again.</source>
        <translation>角度从 %1° 变为 %2°，但不是 0：电机在转动吗？请先停止再清除。</translation>
    </message>
    <message>
        <source>Write zero to ROM</source>
        <translation>写入零点到 ROM</translation>
    </message>
    <message>
        <source>Store the present position of drive %1 as its zero in ROM?</source>
        <translation>将驱动 %1 的当前位置作为零点存入 ROM？</translation>
    </message>
    <message>
        <source>It takes effect only after the drive is powered off and on again. It writes the drive&apos;s flash, which wears with every write: do it once, not as a routine.</source>
        <translation>断电再上电后才生效。它会写入驱动的闪存，每次写入都会磨损：只做一次，不要作为例行操作。</translation>
    </message>
    <message>
        <source>Zero written to the ROM of drive %1. Power the drive off and on for it to take effect.</source>
        <translation>零点已写入驱动 %1 的 ROM。请将驱动断电再上电使其生效。</translation>
    </message>
    <message>
        <source>The drive reports the new zero as encoder %1.</source>
        <translation>驱动报告新零点为编码器 %1。</translation>
    </message>
    <message>
        <source>Clear turn count</source>
        <translation>清除圈数</translation>
    </message>
    <message>
        <source>Set the turn count of drive %1 to 0?</source>
        <translation>将驱动 %1 的圈数设为 0？</translation>
    </message>
    <message>
        <source>The multi-turn angle keeps only the angle within the present turn, so multi-turn position commands go elsewhere afterwards. The V2.35 document does not say whether this survives a power cycle (RAM or ROM) or whether the motor must be off: stop the motor first.</source>
        <translation>多圈角度只保留当前圈内的角度，因此之后的多圈位置命令会走到别的位置。V2.35 文档没有说明这在断电重启后是否保留（RAM 还是 ROM），也没有说明电机是否必须关闭：请先停止电机。</translation>
    </message>
    <message>
        <source>Clearing the turn count of drive %1…</source>
        <translation>正在清除驱动 %1 的圈数…</translation>
    </message>
    <message>
        <source>Turn count of drive %1 cleared: the multi-turn angle reads %2° (was %3°).</source>
        <translation>驱动 %1 的圈数已清除：多圈角度读数为 %2°（原为 %3°）。</translation>
    </message>
    <message>
        <source>Drive %1 acknowledged 0x93, but its multi-turn angle reads %2° (was %3°): more than one turn, so the turn count was not cleared.</source>
        <translation>驱动 %1 确认了 0x93，但其多圈角度读数为 %2°（原为 %3°）：超过一圈，因此圈数没有被清除。</translation>
    </message>
</context>
<context>
    <name>lk::ui::FleetGrid</name>
    <message>
        <source>ID %1
not read</source>
        <translation>ID %1
未读取</translation>
    </message>
    <message>
        <source>ID %1
%2
%3</source>
        <translation>ID %1
%2
%3</translation>
    </message>
    <message>
        <source>Read on this connection at %1 (UTC)</source>
        <translation>在本次连接中于 %1（UTC）读取</translation>
    </message>
    <message>
        <source>Not every value was read: %1</source>
        <translation>并非所有值都已读取：%1</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Differs from drive %1 (%2)</source>
        <translation>与驱动 %1 不同（%2）</translation>
    </message>
    <message>
        <source>ID %1
%2 (declared)
%3</source>
        <translation>ID %1
%2（用户声明）
%3</translation>
    </message>
    <message>
        <source>series unknown</source>
        <translation>系列未知</translation>
    </message>
</context>
<context>
    <name>lk::ui::FleetWriteDialog</name>
    <message>
        <source>Reading the target drives before anything is written...</source>
        <translation>在写入任何内容之前先读取目标驱动……</translation>
    </message>
    <message>
        <source>Write to RAM</source>
        <translation>写入 RAM</translation>
    </message>
    <message>
        <source>Writes the values that change, then reads every target back. Lost at power-off.</source>
        <translation>写入会改变的值，然后回读每个目标驱动。断电后丢失。</translation>
    </message>
    <message>
        <source>Write to ROM...</source>
        <translation>写入 ROM…</translation>
    </message>
    <message>
        <source>RAM first and read back; then, for each drive that matched, the ROM frames once each (asks first).</source>
        <translation>先写 RAM 并回读；然后对回读一致的每个驱动，每个 ROM 帧各发送一次（会先确认）。</translation>
    </message>
    <message>
        <source>Drive %1 of %2 ...</source>
        <translation>第 %1 个驱动，共 %2 个……</translation>
    </message>
    <message>
        <source>Drive %1 from drive %2: </source>
        <translation>驱动 %1（来自驱动 %2）：</translation>
    </message>
    <message>
        <source>refused, nothing will be sent to it (%1): %2</source>
        <translation>被拒绝，不会向它发送任何内容（%1）：%2</translation>
    </message>
    <message>
        <source>already holds every value</source>
        <translation>已持有全部值</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) change</source>
        <translation>
            <numerusform>%n 个值将改变</numerusform>
        </translation>
    </message>
    <message>
        <source>The targets&apos; values could not be saved (%1): nothing will be written.</source>
        <translation>无法保存目标驱动的当前值（%1）：不会写入任何内容。</translation>
    </message>
    <message>
        <source>Targets read; their values are saved in %1 (a backup: restoring it undoes this). Nothing has been written yet.</source>
        <translation>已读取目标驱动；其当前值保存在 %1（这是一个备份：恢复它即可撤销本次操作）。尚未写入任何内容。</translation>
    </message>
    <message>
        <source>Write to ROM</source>
        <translation>写入 ROM</translation>
    </message>
    <message>
        <source>Write these values to the ROM of every drive that is not refused?</source>
        <translation>将这些值写入每个未被拒绝的驱动的 ROM？</translation>
    </message>
    <message>
        <source>ROM is the drives&apos; flash: each write wears it, and the values stay after power-off. RAM is written and read back first; ROM only where it matched, each frame once, never repeated. V2.3 drives cannot read ROM back: the report says what was not verified.</source>
        <translation>ROM 是驱动的闪存：每次写入都会磨损它，写入的值断电后仍然保留。先写 RAM 并回读；只有回读一致的驱动才写 ROM，每帧只发送一次，绝不重发。V2.3 驱动无法回读 ROM：报告会说明哪些未经核对。</translation>
    </message>
    <message>
        <source>Cancelled: nothing was sent.</source>
        <translation>已取消：未发送任何命令。</translation>
    </message>
    <message>
        <source>Writing ...</source>
        <translation>正在写入……</translation>
    </message>
    <message>
        <source>verified: written and read back equal</source>
        <translation>已核对：写入后回读一致</translation>
    </message>
    <message>
        <source>written, not all of it verifiable</source>
        <translation>已写入，但不能全部核对</translation>
    </message>
    <message>
        <source>unchanged: it already held every value, nothing was sent</source>
        <translation>未改变：它已持有全部值，未发送任何内容</translation>
    </message>
    <message>
        <source>differs: the read-back is not what was written</source>
        <translation>不一致：回读值与写入值不同</translation>
    </message>
    <message>
        <source>refused: nothing was sent</source>
        <translation>被拒绝：未发送任何内容</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>Drive %1: %2</source>
        <translation>驱动 %1：%2</translation>
    </message>
    <message>
        <source>Done. The values before are in %1.</source>
        <translation>完成。写入前的值保存在 %1。</translation>
    </message>
    <message>
        <source>The targets are CAN V2.36 drives: their control parameters are RAM only (0xC1), there is no ROM write. Write to RAM instead.</source>
        <translation>目标为 CAN V2.36 驱动器：其控制参数仅存于 RAM（0xC1），没有 ROM 写入。请改为写入 RAM。</translation>
    </message>
    <message>
        <source> (RAM only: CAN V2.36 has no ROM for these parameters; Write to RAM writes it, Write to ROM refuses it and sends it nothing)</source>
        <translation>（仅 RAM：CAN V2.36 的这些参数没有 ROM；“写入 RAM”会写入它，“写入 ROM”会拒绝它且不向它发送任何内容）</translation>
    </message>
</context>
<context>
    <name>lk::ui::Format</name>
    <message>
        <source>Error bit %1</source>
        <translation>错误位 %1</translation>
    </message>
    <message>
        <source>No errors</source>
        <translation>无错误</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>已连接：%1</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>已断开</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>rel.</source>
        <translation>相对值</translation>
    </message>
    <message>
        <source>%1 Mbit/s</source>
        <translation>%1 Mbit/s</translation>
    </message>
    <message>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <source>%1 bit/s</source>
        <translation>%1 bit/s</translation>
    </message>
    <message>
        <source>CAN errors (warning level), frames still get through</source>
        <translation>CAN 错误（警告级别），帧仍可通过</translation>
    </message>
    <message>
        <source>CAN error-passive: many frames fail</source>
        <translation>CAN 错误被动：大量帧失败</translation>
    </message>
    <message>
        <source>CAN bus-off: the adapter stopped sending</source>
        <translation>CAN 离线（bus-off）：适配器已停止发送</translation>
    </message>
    <message>
        <source>no acknowledgement: no drive powered, or another bit rate</source>
        <translation>无应答：没有驱动上电，或比特率不同</translation>
    </message>
    <message>
        <source>Listen-only: this tool transmits nothing (%1)</source>
        <translation>仅监听：本工具不发送任何内容（%1）</translation>
    </message>
</context>
<context>
    <name>lk::ui::FrequencyResponseView</name>
    <message>
        <source>Measure</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>Clear runs</source>
        <translation>清除运行记录</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> °/s</translation>
    </message>
    <message>
        <source>The speed the sine is centred on. Away from 0, so that the rotor never stops: friction would bend the response.</source>
        <translation>正弦的中心速度。应远离 0，使转子不会停转：摩擦会使响应失真。</translation>
    </message>
    <message>
        <source>The sine&apos;s peak around the operating point.</source>
        <translation>正弦在工作点附近的峰值。</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Each frequency lasts at least this long (and 5 cycles).</source>
        <translation>每个频率至少持续这么久（且至少 5 个周期）。</translation>
    </message>
    <message>
        <source>Operating point ± amplitude</source>
        <translation>工作点 ± 幅值</translation>
    </message>
    <message>
        <source>From → to</source>
        <translation>从 → 到</translation>
    </message>
    <message>
        <source>Frequencies, each at least</source>
        <translation>频率个数，每个至少</translation>
    </message>
    <message>
        <source>The sweep cannot run as set (%1). Nothing was sent.</source>
        <translation>扫频无法按当前设置运行（%1）。未发送任何内容。</translation>
    </message>
    <message>
        <source>Frequency response</source>
        <translation>频率响应</translation>
    </message>
    <message>
        <source>Cancelled: nothing was sent.</source>
        <translation>已取消：未发送任何内容。</translation>
    </message>
    <message>
        <source>The drive or the connection changed: nothing was sent.</source>
        <translation>驱动器或连接已改变：未发送任何内容。</translation>
    </message>
    <message>
        <source>Reading the gains and speed of drive %1…</source>
        <translation>正在读取驱动 %1 的增益和速度…</translation>
    </message>
    <message>
        <source>Sweeping drive %1: %2 frequencies over %3 s. Esc stops it.</source>
        <translation>正在对驱动 %1 扫频：%2 个频率，共 %3 秒。按 Esc 停止。</translation>
    </message>
    <message>
        <source>%1 points at %2 samples/s. %3 %4</source>
        <translation>%1 个点，采样率 %2 次/秒。%3 %4</translation>
    </message>
    <message>
        <source>Refused at %1 dps: %2.</source>
        <translation>在 %1 dps 处被拒绝：%2。</translation>
    </message>
    <message>
        <source>Stop (Esc)</source>
        <translation>停止 (Esc)</translation>
    </message>
    <message>
        <source>Stop at once: Motor Off, and the gains read back to RAM.</source>
        <translation>立即停止：电机关闭，并把读取的增益写回 RAM。</translation>
    </message>
    <message>
        <source>Measure the frequency response set above on the selected drive (asks first).</source>
        <translation>在所选驱动上测量上面设置的频率响应（先询问）。</translation>
    </message>
    <message>
        <source>Measures the speed loop&apos;s frequency response: a sine of the speed setpoint around the operating point, one frequency after the other. Its extremes are checked against the soft limits (Control view) before anything moves; Esc stops the motor and puts the gains read back. The position loop&apos;s is offered while an angle range is set: a sine of the angle around where the drive is.</source>
        <translation>测量速度环的频率响应：速度设定值围绕工作点做正弦变化，逐个频率进行。在任何运动之前，其极值都会按软限位（控制视图）检查；Esc 立即停止电机并写回读取的增益。设置了角度范围时还可测量位置环：角度围绕驱动器当前位置做正弦变化。</translation>
    </message>
    <message>
        <source>Speed loop</source>
        <translation>速度环</translation>
    </message>
    <message>
        <source>Position loop</source>
        <translation>位置环</translation>
    </message>
    <message>
        <source>The position loop needs an angle range (Control view): its sine stays inside it, around where the drive is.</source>
        <translation>位置环需要角度范围（控制视图）：正弦围绕驱动器当前位置，始终保持在该范围内。</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>环</translation>
    </message>
    <message>
        <source> deg</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Refused at %1°: %2.</source>
        <translation>在 %1° 处被拒绝：%2。</translation>
    </message>
    <message>
        <source>Save run…</source>
        <translation>保存运行…</translation>
    </message>
    <message>
        <source>Open run…</source>
        <translation>打开运行…</translation>
    </message>
    <message>
        <source>Remove run</source>
        <translation>移除此运行</translation>
    </message>
    <message>
        <source>Take the chosen run off the chart (a saved file stays).</source>
        <translation>将所选运行从图中移除（已保存的文件保留）。</translation>
    </message>
    <message>
        <source>Save frequency run</source>
        <translation>保存频率响应运行</translation>
    </message>
    <message>
        <source>Frequency runs (*%1)</source>
        <translation>频率响应运行 (*%1)</translation>
    </message>
    <message>
        <source>Open frequency run</source>
        <translation>打开频率响应运行</translation>
    </message>
    <message>
        <source>Frequency runs (*%1);;All files (*)</source>
        <translation>频率响应运行 (*%1);;所有文件 (*)</translation>
    </message>
    <message>
        <source>%1 was not saved: %2</source>
        <translation>%1 未保存：%2</translation>
    </message>
    <message>
        <source>%1 saved to %2.</source>
        <translation>%1 已保存到 %2。</translation>
    </message>
    <message>
        <source>%1 is %2: it must be %3</source>
        <translation>%1 为 %2：它必须是%3</translation>
    </message>
    <message>
        <source>%1 was not opened: %2</source>
        <translation>未打开 %1：%2</translation>
    </message>
    <message>
        <source>%1 is a position loop&apos;s response: it is shown when the position loop is chosen (an angle range is set).</source>
        <translation>%1 是位置环的响应：选择位置环时显示（需设置角度范围）。</translation>
    </message>
    <message>
        <source>Opened %1.</source>
        <translation>已打开 %1.</translation>
    </message>
    <message>
        <source>gains unknown</source>
        <translation>增益未知</translation>
    </message>
    <message>
        <source>Kp %1 Ki %2 Kd %3</source>
        <translation>Kp %1 Ki %2 Kd %3</translation>
    </message>
    <message>
        <source>%1: drive %2, %3, %4, %5</source>
        <translation>%1：驱动器 %2，%3，%4，%5</translation>
    </message>
    <message>
        <source>position loop</source>
        <translation>位置环</translation>
    </message>
    <message>
        <source>speed loop</source>
        <translation>速度环</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>未发送任何内容。</translation>
    </message>
    <message>
        <source>Reading the gains and angle of drive %1…</source>
        <translation>正在读取驱动器 %1 的增益和角度…</translation>
    </message>
</context>
<context>
    <name>lk::ui::FrequencyTuningView</name>
    <message>
        <source>Bode</source>
        <translation>伯德图</translation>
    </message>
    <message>
        <source>Suggested gains</source>
        <translation>建议增益</translation>
    </message>
</context>
<context>
    <name>lk::ui::GainSearchView</name>
    <message>
        <source>within the bounds</source>
        <translation>在界限内</translation>
    </message>
    <message>
        <source>overshoots</source>
        <translation>超调过大</translation>
    </message>
    <message>
        <source>oscillates</source>
        <translation>振荡</translation>
    </message>
    <message>
        <source>did not settle</source>
        <translation>未稳定</translation>
    </message>
    <message>
        <source>current at its limit: unstable, search stopped</source>
        <translation>电流达到限值：不稳定，搜索已停止</translation>
    </message>
    <message>
        <source>swings growing: unstable, search stopped</source>
        <translation>振荡逐渐增大：不稳定，搜索已停止</translation>
    </message>
    <message>
        <source>Search gains</source>
        <translation>搜索增益</translation>
    </message>
    <message>
        <source>Write to RAM</source>
        <translation>写入 RAM</translation>
    </message>
    <message>
        <source>Write to ROM…</source>
        <translation>写入 ROM…</translation>
    </message>
    <message>
        <source>Keep the suggested gains written to RAM: asks first, then writes them to ROM.</source>
        <translation>保留已写入 RAM 的建议增益：先询问，然后写入 ROM。</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Kp</source>
        <translation>Kp</translation>
    </message>
    <message>
        <source>Ki</source>
        <translation>Ki</translation>
    </message>
    <message>
        <source>Rise</source>
        <translation>上升时间</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>超调</translation>
    </message>
    <message>
        <source>Error area</source>
        <translation>误差面积</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>A candidate whose step overshoots more than this is not suggested.</source>
        <translation>阶跃超调大于此值的候选不会被建议。</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> °/s</translation>
    </message>
    <message>
        <source>Each candidate steps the speed between these two, away from 0 where friction would bend the steps.</source>
        <translation>每个候选在这两个速度之间阶跃，远离 0（摩擦会使阶跃失真）。</translation>
    </message>
    <message>
        <source>Max overshoot</source>
        <translation>最大超调</translation>
    </message>
    <message>
        <source>Steps between</source>
        <translation>阶跃区间</translation>
    </message>
    <message>
        <source>Candidates at most</source>
        <translation>最多候选数</translation>
    </message>
    <message>
        <source>Suggested gains</source>
        <translation>建议增益</translation>
    </message>
    <message>
        <source>Cancelled: nothing was sent.</source>
        <translation>已取消：未发送任何内容。</translation>
    </message>
    <message>
        <source>The drive or the connection changed: nothing was sent.</source>
        <translation>驱动器或连接已改变：未发送任何内容。</translation>
    </message>
    <message>
        <source>Searching the speed-loop gains of drive %1… Esc stops it.</source>
        <translation>正在搜索驱动 %1 的速度环增益… 按 Esc 停止。</translation>
    </message>
    <message>
        <source>read</source>
        <translation>读取值</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <source>Candidate %1 of at most %2 tried on drive %3… Esc stops it.</source>
        <translation>已在驱动 %3 上尝试第 %1 个候选（最多 %2 个）… 按 Esc 停止。</translation>
    </message>
    <message>
        <source>Nothing was written: there is no suggestion yet.</source>
        <translation>未写入任何内容：尚无建议值。</translation>
    </message>
    <message>
        <source>Nothing was written: the suggestion is for drive %1, which is not the drive selected and read on this connection.</source>
        <translation>未写入任何内容：该建议针对驱动 %1，它不是本次连接中所选并已读取的驱动。</translation>
    </message>
    <message>
        <source>Nothing was written: the drive&apos;s gains are not all known.</source>
        <translation>未写入任何内容：驱动的增益并未全部已知。</translation>
    </message>
    <message>
        <source>Nothing was written: wait until the drive is idle.</source>
        <translation>未写入任何内容：请等待驱动空闲。</translation>
    </message>
    <message>
        <source>The suggested gains went to the RAM of drive %1 (PID gains shows the read-back). Try them with a step test or a sweep; Write to ROM keeps them.</source>
        <translation>建议增益已写入驱动 %1 的 RAM（“PID 增益”显示回读值）。可用阶跃测试或扫频试用；“写入 ROM”会保留它们。</translation>
    </message>
    <message>
        <source>Nothing was written: write the suggestion to RAM first.</source>
        <translation>未写入任何内容：请先把建议值写入 RAM。</translation>
    </message>
    <message>
        <source>Nothing was written: the drive does not hold the suggested gains in RAM (read back). Write to RAM again first.</source>
        <translation>未写入任何内容：驱动 RAM 中（回读）并不是建议的增益。请先重新写入 RAM。</translation>
    </message>
    <message>
        <source>Stop (Esc)</source>
        <translation>停止 (Esc)</translation>
    </message>
    <message>
        <source>Stop at once: Motor Off, and the gains read back to RAM.</source>
        <translation>立即停止：电机关闭，并把读取的增益写回 RAM。</translation>
    </message>
    <message>
        <source>Measure the Bode of both</source>
        <translation>测量两者的伯德图</translation>
    </message>
    <message>
        <source>After the search, measure the speed loop&apos;s frequency response with the gains read and with the suggested gains (written to RAM for that sweep only, the gains read put back after it).</source>
        <translation>搜索结束后，分别用读取的增益和建议的增益测量速度环的频率响应（建议增益仅在该次扫频期间写入 RAM，扫频后写回读取的增益）。</translation>
    </message>
    <message>
        <source>The Bode of both is refused within these limits: clear the box or change the steps. Nothing was sent.</source>
        <translation>在这些限制内无法测量两者的伯德图：请取消勾选或更改阶跃。未发送任何内容。</translation>
    </message>
    <message>
        <source>Measuring the Bode of the suggested gains on drive %1 (in RAM for this sweep only, %2 s)… Esc stops it.</source>
        <translation>正在测量驱动器 %1 建议增益的伯德图（仅在本次扫频期间位于 RAM，%2 秒）… 按 Esc 停止。</translation>
    </message>
    <message>
        <source>Measuring the Bode of the gains read on drive %1 (%2 s)… Esc stops it.</source>
        <translation>正在测量驱动器 %1 读取增益的伯德图（%2 秒）… 按 Esc 停止。</translation>
    </message>
    <message>
        <source>The Bode of both adds about %1 s.</source>
        <translation>测量两者的伯德图约增加 %1 秒。</translation>
    </message>
    <message>
        <source>The Bode of both is refused within these limits: clear the box or change the steps.</source>
        <translation>在这些限制内无法测量两者的伯德图：请取消勾选或更改阶跃。</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Write the suggested Kp and Ki to the drive&apos;s RAM (lost at power-off), then read back. Nothing is written before this.</source>
        <translation>把建议的 Kp 和 Ki 写入驱动的 RAM（断电后丢失），然后回读。在此之前不会写入任何内容。</translation>
    </message>
    <message>
        <source>Tries speed-loop gains (or, with an angle window, position-loop gains) with short steps within the soft limits and suggests the fastest whose overshoot stays under the bound. Nothing is kept in the drive: the gains read go back to RAM at the end.</source>
        <translation>在软限位内用短阶跃尝试速度环增益（设置了角度范围时也可尝试位置环增益），建议超调不超过界限的最快增益。驱动中不会保留任何改动：结束时读取的增益写回 RAM。</translation>
    </message>
    <message>
        <source>Speed loop</source>
        <translation>速度环</translation>
    </message>
    <message>
        <source>Position loop</source>
        <translation>位置环</translation>
    </message>
    <message>
        <source>The position loop is offered while an angle range (both ends) is set: its steps go from the angle the drive is at and back, inside the range.</source>
        <translation>只有设置了角度范围（两端）时才提供位置环：其阶跃从驱动当前角度出发再返回，保持在范围内。</translation>
    </message>
    <message>
        <source> deg</source>
        <translation> 度</translation>
    </message>
    <message>
        <source>Each candidate steps the angle this far from where the drive is and back (down when the range has no room above).</source>
        <translation>每个候选让角度从驱动当前位置阶跃这么远再返回（上方没有空间时向下）。</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>控制环</translation>
    </message>
    <message>
        <source>Step size</source>
        <translation>阶跃幅度</translation>
    </message>
    <message>
        <source>Searching the position-loop gains of drive %1… Esc stops it.</source>
        <translation>正在搜索驱动 %1 的位置环增益… 按 Esc 停止。</translation>
    </message>
    <message>
        <source>Search the gains of the selected drive&apos;s loop (asks first).</source>
        <translation>搜索所选驱动该控制环的增益（先询问）。</translation>
    </message>
</context>
<context>
    <name>lk::ui::GainSearchViewComparison</name>
    <message>
        <source>Gains read</source>
        <translation>读取的增益</translation>
    </message>
    <message>
        <source>Suggested</source>
        <translation>建议值</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>阶跃</translation>
    </message>
    <message>
        <source>Bode</source>
        <translation>伯德图</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>未到达</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>%1 dB at %2 Hz</source>
        <translation>%2 Hz 处 %1 dB</translation>
    </message>
    <message>
        <source>none within the bounds</source>
        <translation>没有在界限内的</translation>
    </message>
    <message>
        <source>Rise</source>
        <translation>上升时间</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>超调</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>未测量</translation>
    </message>
    <message>
        <source>Bandwidth (-3 dB)</source>
        <translation>带宽（-3 dB）</translation>
    </message>
    <message>
        <source>Peak</source>
        <translation>峰值</translation>
    </message>
    <message>
        <source>%1 Kp</source>
        <translation>%1 Kp</translation>
    </message>
    <message>
        <source>%1 Ki</source>
        <translation>%1 Ki</translation>
    </message>
</context>
<context>
    <name>lk::ui::GainSearchViewOutcome</name>
    <message numerus="yes">
        <source>%n candidate(s) tried in %1 s; the best is in bold, Write to RAM tries it. Nothing else was kept.</source>
        <translation>
            <numerusform>在 %1 秒内尝试了 %n 组候选参数；最佳一组以粗体显示，“写入 RAM”将试用它。其他内容均未保留。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n candidate(s) tried in %1 s; none stayed within the bounds.</source>
        <translation>
            <numerusform>在 %1 秒内尝试了 %n 组候选参数；没有一组保持在限值之内。</numerusform>
        </translation>
    </message>
    <message>
        <source>The search stopped at the first unstable candidate.</source>
        <translation>搜索在第一个不稳定的候选处停止。</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>已停止。</translation>
    </message>
    <message>
        <source>Stopped by an emergency stop.</source>
        <translation>已停止：紧急停止。</translation>
    </message>
    <message>
        <source>Refused by a soft limit.</source>
        <translation>被软限位拒绝。</translation>
    </message>
    <message>
        <source>Refused: %1.</source>
        <translation>已拒绝：%1。</translation>
    </message>
    <message>
        <source>It cannot run as set.</source>
        <translation>按当前设置无法运行。</translation>
    </message>
    <message>
        <source>The gains of drive %1 could not be read.</source>
        <translation>无法读取驱动器 %1 的增益。</translation>
    </message>
    <message>
        <source>Drive %1 did not answer: it stopped.</source>
        <translation>驱动 %1 未应答：已停止。</translation>
    </message>
    <message>
        <source>The link went down: it stopped.</source>
        <translation>链路断开：已停止。</translation>
    </message>
    <message>
        <source>The gains read could not be written back at the end: it stopped.</source>
        <translation>结束时无法写回读取的增益：已停止。</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>未发送任何内容。</translation>
    </message>
    <message>
        <source>No step was sent.</source>
        <translation>未发送任何阶跃。</translation>
    </message>
    <message>
        <source>Motor Off went to drive %1 and it acknowledged.</source>
        <translation>已向驱动 %1 发送“电机关闭”，驱动已确认。</translation>
    </message>
    <message>
        <source>Drive %1 did not acknowledge Motor Off: it may still be moving.</source>
        <translation>驱动 %1 未确认“电机关闭”：它可能仍在运动。</translation>
    </message>
    <message>
        <source>Drive %1 holds 0 dps, its motor stays on.</source>
        <translation>驱动器 %1 保持 0 dps，电机保持开启。</translation>
    </message>
    <message>
        <source>Drive %1 is back at %2 dps, the speed it had, and keeps turning until stopped.</source>
        <translation>驱动器 %1 已回到原来的速度 %2 dps，并持续转动直到停止。</translation>
    </message>
    <message>
        <source>The gains read are back in RAM.</source>
        <translation>读取的增益已写回 RAM。</translation>
    </message>
    <message>
        <source>The gains read before could NOT be written back: read the drive and check them.</source>
        <translation>之前读取的增益未能写回：请读取驱动并检查。</translation>
    </message>
    <message>
        <source>Drive %1 holds %2 deg, the angle it started at, its motor stays on.</source>
        <translation>驱动 %1 保持在开始时的角度 %2 度，电机保持开启。</translation>
    </message>
</context>
<context>
    <name>lk::ui::HelpMenu</name>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>Copy &amp;diagnostics</source>
        <translation>复制诊断信息(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;About LK Servo Studio</source>
        <translation>关于 LK Servo Studio(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
    <message>
        <source>Diagnostics copied to the clipboard</source>
        <translation>诊断信息已复制到剪贴板</translation>
    </message>
</context>
<context>
    <name>lk::ui::JogPanel</name>
    <message>
        <source>Jog</source>
        <translation>点动</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> dps</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Arrow keys jog (← → hold, ↓ ↑ step)</source>
        <translation>方向键点动（← → 按住，↓ ↑ 步进）</translation>
    </message>
    <message>
        <source>Only while this view has the focus and no text field does.</source>
        <translation>仅当此页获得焦点且没有文本框获得焦点时有效。</translation>
    </message>
    <message>
        <source>◀ Hold</source>
        <translation>◀ 按住</translation>
    </message>
    <message>
        <source>Runs counter-clockwise at the jog speed while pressed</source>
        <translation>按住时以点动速度逆时针转动</translation>
    </message>
    <message>
        <source>Hold ▶</source>
        <translation>按住 ▶</translation>
    </message>
    <message>
        <source>Runs clockwise at the jog speed while pressed</source>
        <translation>按住时以点动速度顺时针转动</translation>
    </message>
    <message>
        <source>− Step</source>
        <translation>− 步进</translation>
    </message>
    <message>
        <source>One incremental move counter-clockwise</source>
        <translation>逆时针增量移动一步</translation>
    </message>
    <message>
        <source>Step +</source>
        <translation>步进 +</translation>
    </message>
    <message>
        <source>One incremental move clockwise</source>
        <translation>顺时针增量移动一步</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <source>Step:</source>
        <translation>步长：</translation>
    </message>
</context>
<context>
    <name>lk::ui::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <source>The new language takes effect after a restart of LK Servo Studio.</source>
        <translation>新的语言将在重新启动 LK Servo Studio 后生效。</translation>
    </message>
</context>
<context>
    <name>lk::ui::LeaveGuard</name>
    <message>
        <source>Left running at the user&apos;s choice: %1.</source>
        <translation>按用户选择保持运行：%1。</translation>
    </message>
    <message>
        <source>Not stopped, the bus is not connected: %1 may still be moving.</source>
        <translation>未停止，总线未连接：%1 可能仍在运动。</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>退出</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <source>Drive %1 may still be moving</source>
        <translation>驱动器 %1 可能仍在运动</translation>
    </message>
    <message>
        <source>Drives %1 may still be moving</source>
        <translation>驱动器 %1 可能仍在运动</translation>
    </message>
    <message>
        <source>%1 and the bus is not connected: quit anyway?</source>
        <translation>%1，且总线未连接：仍要退出吗？</translation>
    </message>
    <message>
        <source>%1 and the bus is not connected: disconnect anyway?</source>
        <translation>%1，且总线未连接：仍要断开吗？</translation>
    </message>
    <message>
        <source>Commanded to move: %1. Nothing can be sent to stop them now; they keep their last command until their input-timeout protection (if set) stops them.</source>
        <translation>已下达运动指令：%1。现在无法发送任何指令使其停止；它们会保持最后的指令，直到其输入超时保护（如已设置）使其停止。</translation>
    </message>
    <message>
        <source>Quit anyway</source>
        <translation>仍然退出</translation>
    </message>
    <message>
        <source>Disconnect anyway</source>
        <translation>仍然断开</translation>
    </message>
    <message>
        <source>Stop drive %1 before quitting?</source>
        <translation>退出前停止驱动器 %1 吗？</translation>
    </message>
    <message>
        <source>Stop drives %1 before quitting?</source>
        <translation>退出前停止驱动器 %1 吗？</translation>
    </message>
    <message>
        <source>Stop drive %1 before disconnecting?</source>
        <translation>断开前停止驱动器 %1 吗？</translation>
    </message>
    <message>
        <source>Stop drives %1 before disconnecting?</source>
        <translation>断开前停止驱动器 %1 吗？</translation>
    </message>
    <message>
        <source>Commanded to move on this connection: %1. Left running, they keep their last command after lkstudio has let go of the bus; they stop by themselves only if their input-timeout protection is set.</source>
        <translation>本次连接中已下达运动指令：%1。若保持运行，lkstudio 释放总线后它们会保持最后的指令；只有设置了输入超时保护，它们才会自行停止。</translation>
    </message>
    <message>
        <source>Stop and quit</source>
        <translation>停止并退出</translation>
    </message>
    <message>
        <source>Stop and disconnect</source>
        <translation>停止并断开</translation>
    </message>
    <message>
        <source>Leave running</source>
        <translation>保持运行</translation>
    </message>
    <message>
        <source>The demo&apos;s simulated drives were stopped.</source>
        <translation>演示中的模拟驱动器已停止。</translation>
    </message>
    <message>
        <source>Motor Off (0x80) acknowledged by drive %1.</source>
        <translation>驱动器 %1 已确认电机关闭（0x80）。</translation>
    </message>
    <message>
        <source>Motor Off (0x80) acknowledged by drives %1.</source>
        <translation>驱动器 %1 已确认电机关闭（0x80）。</translation>
    </message>
    <message>
        <source>%1 did not acknowledge Motor Off: it may still be moving.</source>
        <translation>%1 未确认电机关闭：它可能仍在运动。</translation>
    </message>
</context>
<context>
    <name>lk::ui::LinkLossWatch</name>
    <message>
        <source>&lt;b&gt;Drive %1 may still be moving&lt;/b&gt;: last command %2 at %3; it stops by itself only if its input-timeout protection is set.</source>
        <translation>&lt;b&gt;驱动 %1 可能仍在运动&lt;/b&gt;：最后的命令是 %3 时的 %2；只有设置了输入超时保护，它才会自行停止。</translation>
    </message>
</context>
<context>
    <name>lk::ui::ListenOnlyControl</name>
    <message>
        <source>Take over the bus</source>
        <translation>接管总线</translation>
    </message>
    <message>
        <source>Take over %1 and become its bus master?</source>
        <translation>接管 %1 并成为其总线主站？</translation>
    </message>
    <message>
        <source>This tool will transmit: it reopens the port read-write, polls the drives, and its commands and emergency stop go out. If the machine&apos;s own controller is still running, both transmit on the same wires: frames collide and neither controls the drives reliably. Stop the machine&apos;s controller (or disconnect it from the bus) first.</source>
        <translation>本工具将会发送：它以读写方式重新打开端口、轮询驱动器，其命令和急停都会发出。如果机器自己的控制器仍在运行，两者会在同一对线上发送：帧会冲突，谁都无法可靠地控制驱动器。请先停止机器的控制器（或把它从总线上断开）。</translation>
    </message>
    <message>
        <source>Take over</source>
        <translation>接管</translation>
    </message>
</context>
<context>
    <name>lk::ui::ListenStatisticsPane</name>
    <message>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <source>Requests/s</source>
        <translation>请求/秒</translation>
    </message>
    <message>
        <source>Requests / replies</source>
        <translation>请求 / 应答</translation>
    </message>
    <message>
        <source>Unanswered</source>
        <translation>未应答</translation>
    </message>
    <message>
        <source>Latency min / median / max</source>
        <translation>延迟 最小 / 中位 / 最大</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Requests</source>
        <translation>请求</translation>
    </message>
    <message>
        <source>Latencies are approximate: requests and replies are timed when the adapter hands them over (up to 16 ms late on an FTDI adapter without the low-latency setting).</source>
        <translation>延迟为近似值：请求和应答的时间是在转换器交出数据时记录的（未设置低延迟的 FTDI 转换器最多晚 16 ms）。</translation>
    </message>
    <message>
        <source>Per drive</source>
        <translation>按驱动器</translation>
    </message>
    <message>
        <source>Per command</source>
        <translation>按命令</translation>
    </message>
    <message>
        <source>%1 CAN error frames, %2 frames of no drive (other IDs, 0x280 included)</source>
        <translation>%1 个 CAN 错误帧，%2 个不属于任何驱动器的帧（其他 ID，含 0x280）</translation>
    </message>
    <message>
        <source>%1 checksum errors, %2 garbage bytes</source>
        <translation>%1 个校验错误，%2 个垃圾字节</translation>
    </message>
    <message>
        <source>The recorded master: %1 requests/s, bus load %2 %; %3 requests, %4 unanswered (its timeouts); %5; %6 replies without their request, %7 echo frames not paired (ambiguous).</source>
        <translation>所记录的主站：%1 请求/秒，总线负载 %2 %；%3 个请求，%4 个未应答（其超时）；%5；%6 个应答没有对应的请求，%7 个回显帧未配对（有歧义）。</translation>
    </message>
    <message>
        <source>The other master: %1 requests/s, bus load %2 %; %3 requests, %4 unanswered (its timeouts); %5; %6 replies without their request, %7 echo frames not paired (ambiguous).</source>
        <translation>另一个主站：%1 请求/秒，总线负载 %2 %；%3 个请求，%4 个未应答（其超时）；%5；%6 个应答没有对应的请求，%7 个回显帧未配对（有歧义）。</translation>
    </message>
</context>
<context>
    <name>lk::ui::LoopPlot</name>
    <message>
        <source>Angle loop: multi-turn angle</source>
        <translation>角度环：多圈角度</translation>
    </message>
    <message>
        <source>Speed loop: speed</source>
        <translation>速度环：速度</translation>
    </message>
    <message>
        <source>Current loop: iq (power on MS)</source>
        <translation>电流环：iq（MS 为功率）</translation>
    </message>
    <message>
        <source>Follows the field you edit; pick another loop here.</source>
        <translation>跟随您正在编辑的字段；也可在此选择其他环路。</translation>
    </message>
    <message>
        <source>Live plot:</source>
        <translation>实时曲线：</translation>
    </message>
    <message>
        <source>Select a drive to see its loop.</source>
        <translation>选择一个驱动以查看其环路。</translation>
    </message>
    <message>
        <source>No samples of this signal yet: the plot shows what the bus polls for drive %1 (polling runs while connected).</source>
        <translation>尚无此信号的采样：曲线显示总线为驱动 %1 轮询的数据（连接时持续轮询）。</translation>
    </message>
    <message>
        <source>Last %1 s of drive %2, rotor values.</source>
        <translation>驱动 %2 最近 %1 s，转子值。</translation>
    </message>
</context>
<context>
    <name>lk::ui::MainWindow</name>
    <message>
        <source>LK Servo Studio</source>
        <translation>LK Servo Studio</translation>
    </message>
    <message>
        <source>Dashboard</source>
        <translation>仪表盘</translation>
    </message>
    <message>
        <source>Overview</source>
        <translation>总览</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>曲线</translation>
    </message>
    <message>
        <source>Traffic</source>
        <translation>通信</translation>
    </message>
    <message>
        <source>Tuning</source>
        <translation>调参</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>控制</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>编码器</translation>
    </message>
    <message>
        <source>Drive info</source>
        <translation>驱动信息</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Export &amp;traffic log…</source>
        <translation>导出通信记录(&amp;T)…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Bus</source>
        <translation>总线(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Scan</source>
        <translation>扫描(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>断开(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Emergency stop (Esc)</source>
        <translation>急停(&amp;E) (Esc)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Take over the bus…</source>
        <translation>接管总线(&amp;T)…</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
</context>
<context>
    <name>lk::ui::MessageBanner</name>
    <message>
        <source>%1 (×%2)</source>
        <translation>%1 (×%2)</translation>
    </message>
</context>
<context>
    <name>lk::ui::MetricText</name>
    <message>
        <source>Rise 10-90 %</source>
        <translation>上升时间 10-90 %</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>超调</translation>
    </message>
    <message>
        <source>Settling 2 %</source>
        <translation>调节时间 2 %</translation>
    </message>
    <message>
        <source>Settling 5 %</source>
        <translation>调节时间 5 %</translation>
    </message>
    <message>
        <source>Steady-state error</source>
        <translation>稳态误差</translation>
    </message>
    <message>
        <source>Peak power</source>
        <translation>峰值功率</translation>
    </message>
    <message>
        <source>Peak iq</source>
        <translation>峰值 iq</translation>
    </message>
    <message>
        <source>At the limit</source>
        <translation>处于限幅</translation>
    </message>
    <message>
        <source>Oscillations</source>
        <translation>振荡次数</translation>
    </message>
    <message>
        <source>Time from the response first crossing 10 % of the step to first crossing 90 % of it (crossings interpolated between samples).</source>
        <translation>响应首次越过阶跃幅值 10 % 到首次越过 90 % 之间的时间（越过时刻在采样点之间线性插值）。</translation>
    </message>
    <message>
        <source>The largest excursion past the target, in % of the step size; 0 when the response never passes the target.</source>
        <translation>越过目标值的最大偏移，以阶跃幅值的百分比表示；响应从未越过目标时为 0。</translation>
    </message>
    <message>
        <source>Target minus the mean response over the last fifth of the step, in the loop&apos;s unit.</source>
        <translation>目标值减去该阶跃最后五分之一时间内响应的平均值，单位与该环相同。</translation>
    </message>
    <message>
        <source>The largest |power| (relative, of 1000) the drive reported during the step.</source>
        <translation>阶跃期间驱动报告的最大 |功率|（相对值，满量程 1000）。</translation>
    </message>
    <message>
        <source>The largest |iq| (torque current) the drive reported during the step.</source>
        <translation>阶跃期间驱动报告的最大 |iq|（转矩电流）。</translation>
    </message>
    <message>
        <source>The longest time the current (power) stayed at 98 % or more of the drive&apos;s limit; runs shorter than 20 ms count as 0. Needs the drive&apos;s limit.</source>
        <translation>电流（功率）持续处于驱动限值 98 % 以上的最长时间；短于 20 ms 的记为 0。需要已知驱动的限值。</translation>
    </message>
    <message>
        <source>Peaks outside the 2 % band after the response first reached the target.</source>
        <translation>响应首次到达目标后，超出 2 % 范围的峰值个数。</translation>
    </message>
    <message>
        <source>too few samples</source>
        <translation>采样点太少</translation>
    </message>
    <message>
        <source>no step</source>
        <translation>无阶跃</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>未到达</translation>
    </message>
    <message>
        <source>never settled</source>
        <translation>未稳定</translation>
    </message>
    <message>
        <source>no current read</source>
        <translation>未读到电流</translation>
    </message>
    <message>
        <source>limit unknown</source>
        <translation>限值未知</translation>
    </message>
    <message>
        <source>Time from the step until the response stays within ±2 % of the step size around the target, to the end of the step.</source>
        <translation>从阶跃开始，到响应此后直至该阶跃结束都保持在目标值 ±2 %（阶跃幅值的百分比）范围内所需的时间。</translation>
    </message>
    <message>
        <source>The same with a ±5 % band.</source>
        <translation>同上，范围为 ±5 %。</translation>
    </message>
    <message>
        <source>Peak iq or power</source>
        <translation>峰值 iq 或功率</translation>
    </message>
</context>
<context>
    <name>lk::ui::MotionGate</name>
    <message>
        <source>Not connected.</source>
        <translation>未连接。</translation>
    </message>
</context>
<context>
    <name>lk::ui::MultiTorquePanel</name>
    <message>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <source>One frame (0x280) with the torque of every ticked drive, each checked against its limits first; sent once, never repeated. The drives must be in their Broadcast Mode (set with the vendor&apos;s tool).</source>
        <translation>一帧（0x280）携带每个已勾选驱动器的转矩，发送前逐个按其限值检查；只发送一次，从不重复。驱动器须处于广播模式（用厂商工具设置）。</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Motor Stop (0x81) to every drive of the last frame</source>
        <translation>向上一帧的每个驱动器发送电机停止（0x81）</translation>
    </message>
    <message>
        <source>%1 Nothing is ticked now and every torque is back to 0 A.</source>
        <translation>%1 现已全部取消勾选，每个转矩都已恢复为 0 A。</translation>
    </message>
    <message>
        <source>The connection changed: nothing is ticked now and every torque is back to 0 A.</source>
        <translation>连接已改变：现已全部取消勾选，每个转矩都已恢复为 0 A。</translation>
    </message>
    <message>
        <source>Drive %1 (%2)</source>
        <translation>驱动器 %1（%2）</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <source>no reply yet</source>
        <translation>尚无应答</translation>
    </message>
    <message>
        <source>CAN generation not known: select drive %1 in the drive list and choose its series and CAN generation (old: 0x140 replies) below it</source>
        <translation>CAN 代次未知：在驱动器列表中选中驱动器 %1，并在列表下方选择其系列和 CAN 代次（旧版：0x140 应答）</translation>
    </message>
    <message>
        <source>CAN V2.36 documents no multi-motor frame</source>
        <translation>CAN V2.36 文档中没有多电机帧</translation>
    </message>
    <message>
        <source>series not known: select drive %1 in the drive list and choose its series below it</source>
        <translation>系列未知：在驱动器列表中选中驱动器 %1，并在列表下方选择其系列</translation>
    </message>
    <message>
        <source>Torque current of drive %1: at most %2 A either way (its limits)</source>
        <translation>驱动器 %1 的转矩电流：正反向最大 %2 A（其限值）</translation>
    </message>
    <message>
        <source>No such frame on RS485: the multi-motor torque frame (0x280) is a CAN frame of the old generation.</source>
        <translation>RS485 上没有此帧：多电机转矩帧（0x280）是旧版 CAN 的帧。</translation>
    </message>
    <message>
        <source>No drive of ID 1..4 is on the bus: the frame (0x280) has slots for IDs 1..4 only.</source>
        <translation>总线上没有 ID 1..4 的驱动器：该帧（0x280）只有 ID 1..4 的槽位。</translation>
    </message>
    <message>
        <source>The CAN generation of drive %1 is not known: select it in the drive list and choose its series and CAN generation (old: 0x140 replies) below it.</source>
        <translation>驱动器 %1 的 CAN 代次未知：在驱动器列表中选中它，并在列表下方选择其系列和 CAN 代次（旧版：0x140 应答）。</translation>
    </message>
    <message>
        <source>Drive %1 speaks CAN V2.36, which documents no multi-motor frame (0x280).</source>
        <translation>驱动器 %1 使用 CAN V2.36，其文档中没有多电机帧（0x280）。</translation>
    </message>
    <message>
        <source>Disconnected: nothing can be sent.</source>
        <translation>未连接：无法发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: drive %1: %2. Nothing sent.</source>
        <translation>已拒绝：驱动器 %1：%2。未发送任何内容。</translation>
    </message>
    <message>
        <source>drive %1 %2 A</source>
        <translation>驱动器 %1 %2 A</translation>
    </message>
    <message>
        <source>Multi-motor torque (0x280) handed to the bus: %1. Waiting for the replies…</source>
        <translation>多电机转矩（0x280）已交给总线：%1。正在等待应答…</translation>
    </message>
    <message>
        <source>Nothing is ticked: tick the drives the frame is for. Nothing sent.</source>
        <translation>没有勾选任何驱动器：请勾选该帧要发给的驱动器。未发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: drive %1 is on the bus, would get 0 A from this frame (it has a slot for each of IDs 1..4) and cannot be ticked: %2. Nothing sent.</source>
        <translation>已拒绝：驱动器 %1 在总线上，会从此帧得到 0 A（该帧为 ID 1..4 各有一个槽位），且无法勾选：%2。未发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: drive %1 is on the bus and would get 0 A from this frame (it has a slot for each of IDs 1..4). Tick drive %1 with 0 A if zero torque is meant. Nothing sent.</source>
        <translation>已拒绝：驱动器 %1 在总线上，会从此帧得到 0 A（该帧为 ID 1..4 各有一个槽位）。如确实要零转矩，请勾选驱动器 %1 并设为 0 A。未发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: the CAN generation of drive %1 is not known: choose it below the drive list. Nothing sent.</source>
        <translation>已拒绝：驱动器 %1 的 CAN 代次未知：请在驱动器列表下方选择。未发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: drive %1 speaks CAN V2.36, which documents no multi-motor frame. Nothing sent.</source>
        <translation>已拒绝：驱动器 %1 使用 CAN V2.36，其文档中没有多电机帧。未发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: the series of drive %1 is not known: choose it below the drive list. Nothing sent.</source>
        <translation>已拒绝：驱动器 %1 的系列未知：请在驱动器列表下方选择。未发送任何内容。</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>已拒绝：%1</translation>
    </message>
    <message>
        <source>Refused by the bus: %1</source>
        <translation>被总线拒绝：%1</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>未发送：%1</translation>
    </message>
    <message>
        <source>iq %1 A, %2 dps, %3 °C</source>
        <translation>iq %1 A，%2 dps，%3 °C</translation>
    </message>
    <message>
        <source>no reply to the last frame</source>
        <translation>上一帧无应答</translation>
    </message>
    <message>
        <source>Sent multi-motor torque (0x280): %1.</source>
        <translation>已发送多电机转矩（0x280）：%1。</translation>
    </message>
    <message>
        <source>Answered: drive(s) %1.</source>
        <translation>已应答：驱动器 %1。</translation>
    </message>
    <message>
        <source>No reply from drive(s) %1 (not in Broadcast Mode, or absent): they may have acted on it all the same; Stop or Esc stops them.</source>
        <translation>驱动器 %1 无应答（未处于广播模式，或不存在）：它们仍可能已执行该帧；按“停止”或 Esc 使其停止。</translation>
    </message>
    <message>
        <source>Sent Motor Stop (0x81) to drive(s) %1.</source>
        <translation>已向驱动器 %1 发送电机停止（0x81）。</translation>
    </message>
</context>
<context>
    <name>lk::ui::OverviewModel</name>
    <message>
        <source>At the output shaft when the motor name gives a gear ratio, else at the rotor</source>
        <translation>型号名给出减速比时为输出轴的值，否则为转子的值</translation>
    </message>
    <message>
        <source>Median time from request to reply over the recent replies</source>
        <translation>最近若干次回复中，从请求到回复的时间中位数</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>FW/HW</source>
        <translation>固件/硬件</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>链路</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Temp.</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>iq/power</source>
        <translation>iq/功率</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Replies</source>
        <translation>回复</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>超时</translation>
    </message>
    <message>
        <source>Checksum err.</source>
        <translation>校验错误</translation>
    </message>
    <message>
        <source>Latency</source>
        <translation>延迟</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>离线</translation>
    </message>
    <message>
        <source>silent</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>过时</translation>
    </message>
    <message>
        <source>live</source>
        <translation>实时</translation>
    </message>
</context>
<context>
    <name>lk::ui::OverviewPanel</name>
    <message numerus="yes">
        <source>%n drive(s) on the bus</source>
        <translation>
            <numerusform>总线上有 %n 个驱动</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) with error flags</source>
        <translation>
            <numerusform>%n 个驱动有错误标志</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 timeouts, %2 checksum errors on the bus</source>
        <translation>总线上 %1 次超时，%2 次校验错误</translation>
    </message>
</context>
<context>
    <name>lk::ui::ParamExchange</name>
    <message>
        <source>the drive&apos;s replies did not carry every value.</source>
        <translation>驱动的应答未包含全部数值。</translation>
    </message>
    <message>
        <source>the drive&apos;s values have not been read.</source>
        <translation>尚未读取驱动的数值。</translation>
    </message>
    <message>
        <source>%1 (%2) of drive %3: %4</source>
        <translation>驱动 %3 的 %1（%2）：%4</translation>
    </message>
    <message>
        <source>drive %1 refused the write of %2 (%3 answered with failure flag %4 for ParamID 0x%5).</source>
        <translation>驱动 %1 拒绝写入 %2（%3 对 参数 ID 0x%5 应答了失败标志 %4）。</translation>
    </message>
    <message>
        <source>the pending edit does not differ from what the drive holds.</source>
        <translation>待写入的修改与驱动保存的值没有差别。</translation>
    </message>
</context>
<context>
    <name>lk::ui::ParamSetSpec</name>
    <message>
        <source>%1: the drive holds %2 after %3 was written.</source>
        <translation>%1：写入 %3 后驱动保存的是 %2。</translation>
    </message>
    <message>
        <source>The read-back did not complete: what the drive holds is not known. Editing and writing stay off until Read from drive succeeds.</source>
        <translation>回读未完成：驱动实际保存的值未知。在“从驱动读取”成功之前，编辑和写入保持禁用。</translation>
    </message>
</context>
<context>
    <name>lk::ui::ParameterFileText</name>
    <message>
        <source>an integer in %1..%2</source>
        <translation>%1..%2 之间的整数</translation>
    </message>
    <message>
        <source>a number in %1..%2</source>
        <translation>%1..%2 之间的数值</translation>
    </message>
    <message>
        <source>text in quotes</source>
        <translation>带引号的文本</translation>
    </message>
    <message>
        <source>an object ({ ... })</source>
        <translation>对象（{ ... }）</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is too large to be a parameter file (more than %2 bytes)</source>
        <translation>%1 太大，不可能是参数文件（超过 %2 字节）</translation>
    </message>
    <message>
        <source>not valid JSON (%1 at byte %2)</source>
        <translation>不是有效的 JSON（%1，位于第 %2 字节）</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>不是 JSON 对象</translation>
    </message>
    <message>
        <source>not an LK Servo Studio parameter file (format is %1, not &quot;%2&quot;)</source>
        <translation>不是 LK Servo Studio 参数文件（format 为 %1，而不是“%2”）</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <source>written by a newer release (format version %1, this one reads up to %2)</source>
        <translation>由更新的版本写入（格式版本 %1，本版本最高只能读取 %2）</translation>
    </message>
    <message>
        <source>%1 is missing: it must be %2</source>
        <translation>缺少 %1：它必须是%2</translation>
    </message>
    <message>
        <source>%1 is not a key of a parameter file (a typing error?)</source>
        <translation>%1 不是参数文件中的键（拼写错误？）</translation>
    </message>
    <message>
        <source>%1 is given twice: which one is meant is not known</source>
        <translation>%1 出现了两次：无法确定以哪一个为准</translation>
    </message>
    <message>
        <source>%1 is %2: it must be %3</source>
        <translation>%1 为 %2：它必须是%3</translation>
    </message>
    <message>
        <source>%1 is %2, out of range: it must be %3</source>
        <translation>%1 为 %2，超出范围：它必须是%3</translation>
    </message>
    <message>
        <source>%1 is %2: it must be MS, MF, MG or MH</source>
        <translation>%1 为 %2：它必须是 MS、MF、MG 或 MH</translation>
    </message>
    <message>
        <source>%1 is %2: it must be a date and time such as &quot;2026-05-04T03:02:01.000Z&quot;</source>
        <translation>%1 为 %2：它必须是日期时间，例如“2026-05-04T03:02:01.000Z”</translation>
    </message>
    <message>
        <source>%1 is %2: it must be &quot;v2.3&quot; or &quot;v2.35&quot;</source>
        <translation>%1 为 %2：必须是 &quot;v2.3&quot; 或 &quot;v2.35&quot;</translation>
    </message>
</context>
<context>
    <name>lk::ui::ParameterTable</name>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Drive holds</source>
        <translation>驱动当前值</translation>
    </message>
    <message>
        <source>Pending edit</source>
        <translation>待写入</translation>
    </message>
    <message>
        <source>Angle loop Kp</source>
        <translation>角度环 Kp</translation>
    </message>
    <message>
        <source>Angle loop Ki</source>
        <translation>角度环 Ki</translation>
    </message>
    <message>
        <source>Speed loop Kp</source>
        <translation>速度环 Kp</translation>
    </message>
    <message>
        <source>Speed loop Ki</source>
        <translation>速度环 Ki</translation>
    </message>
    <message>
        <source>Current loop Kp</source>
        <translation>电流环 Kp</translation>
    </message>
    <message>
        <source>Current loop Ki</source>
        <translation>电流环 Ki</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <source> dps/s</source>
        <translation> dps/s</translation>
    </message>
    <message>
        <source>0x34 writes acceleration to RAM only: protocol V2.3 has no ROM command for it. Some firmware ignores it (read back shows).</source>
        <translation>0x34 只把加速度写入 RAM：协议 V2.3 没有对应的 ROM 命令。部分固件会忽略它（回读可见）。</translation>
    </message>
    <message>
        <source>0..255</source>
        <translation>0..255</translation>
    </message>
    <message>
        <source>First read</source>
        <translation>首次读取</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
</context>
<context>
    <name>lk::ui::ParametersView</name>
    <message>
        <source>Read all</source>
        <translation>全部读取</translation>
    </message>
    <message>
        <source>Reads every parameter of every drive found, one drive after another. Nothing is written.</source>
        <translation>逐个读取已发现的每个驱动的全部参数。不写入任何内容。</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Cells that differ from this drive are marked</source>
        <translation>与该驱动不同的单元格会被标记</translation>
    </message>
    <message>
        <source>Only rows that differ</source>
        <translation>只显示有差异的行</translation>
    </message>
    <message>
        <source>Reference:</source>
        <translation>参考驱动：</translation>
    </message>
    <message>
        <source>Back up...</source>
        <translation>备份…</translation>
    </message>
    <message>
        <source>Saves the values read into one bus backup file</source>
        <translation>把读取的值保存到一个总线备份文件</translation>
    </message>
    <message>
        <source>Restore...</source>
        <translation>恢复…</translation>
    </message>
    <message>
        <source>Writes a backup&apos;s values onto the drives of the same IDs: the targets are read and the changes shown first</source>
        <translation>把备份中的值写入相同 ID 的驱动：会先读取目标驱动并显示将要改变的值</translation>
    </message>
    <message>
        <source>Clone reference...</source>
        <translation>复制参考驱动…</translation>
    </message>
    <message>
        <source>Writes the reference drive&apos;s values onto the other drives read: the targets are read and the changes shown first</source>
        <translation>把参考驱动的值写入已读取的其他驱动：会先读取目标驱动并显示将要改变的值</translation>
    </message>
    <message>
        <source>Back up the bus</source>
        <translation>备份总线</translation>
    </message>
    <message>
        <source>Bus backup (*.json)</source>
        <translation>总线备份 (*.json)</translation>
    </message>
    <message>
        <source>Backed up into %1.</source>
        <translation>已备份到 %1。</translation>
    </message>
    <message>
        <source>Restore a bus backup</source>
        <translation>恢复总线备份</translation>
    </message>
    <message numerus="yes">
        <source>Reading %n drive(s) ...</source>
        <translation>
            <numerusform>正在读取 %n 个驱动……</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cancelled after %n drive(s).</source>
        <translation>
            <numerusform>已在读取 %n 个驱动后取消。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) read.</source>
        <translation>
            <numerusform>已读取 %n 个驱动。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n could not be read completely: their missing values show as unknown.</source>
        <translation>
            <numerusform>%n 个驱动未能完整读取：缺失的值显示为未知。</numerusform>
        </translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>驱动 %1</translation>
    </message>
    <message>
        <source>%1 is refused, nothing was sent: %2</source>
        <translation>%1 被拒绝，未发送任何内容：%2</translation>
    </message>
    <message>
        <source>Restore %1</source>
        <translation>恢复 %1</translation>
    </message>
    <message>
        <source>Clone drive %1</source>
        <translation>复制驱动 %1</translation>
    </message>
    <message>
        <source>ID map, e.g. 3:5</source>
        <translation>ID 映射，例如 3:5</translation>
    </message>
    <message>
        <source>Restore the backup&apos;s drive 3 onto drive 5 (a replaced drive). With a map, only the mapped drives are restored.</source>
        <translation>把备份中的 3 号驱动恢复到 5 号驱动（更换后的驱动）。填写映射后，只恢复映射中的驱动。</translation>
    </message>
    <message>
        <source>The ID map is refused, nothing was sent: %1</source>
        <translation>ID 映射被拒绝，未发送任何内容：%1</translation>
    </message>
    <message>
        <source>%1 holds none of the drives of the ID map: nothing was sent.</source>
        <translation>%1 中没有 ID 映射里的任何驱动：未发送任何内容。</translation>
    </message>
</context>
<context>
    <name>lk::ui::PlotExporter</name>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>nothing plotted</source>
        <translation>未绘制任何信号</translation>
    </message>
    <message>
        <source>drive %1</source>
        <translation>驱动 %1</translation>
    </message>
    <message>
        <source>drives %1</source>
        <translation>驱动 %1</translation>
    </message>
</context>
<context>
    <name>lk::ui::PlotPanel</name>
    <message>
        <source>5 s</source>
        <translation>5 s</translation>
    </message>
    <message>
        <source>10 s</source>
        <translation>10 s</translation>
    </message>
    <message>
        <source>30 s</source>
        <translation>30 s</translation>
    </message>
    <message>
        <source>1 min</source>
        <translation>1 分钟</translation>
    </message>
    <message>
        <source>5 min</source>
        <translation>5 分钟</translation>
    </message>
    <message>
        <source>10 min</source>
        <translation>10 分钟</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Freeze the plots; recording goes on</source>
        <translation>冻结曲线；记录继续进行</translation>
    </message>
    <message>
        <source>Follow live</source>
        <translation>跟随最新</translation>
    </message>
    <message>
        <source>Return to the newest data after zooming or panning</source>
        <translation>缩放或平移后回到最新数据</translation>
    </message>
    <message>
        <source>Window:</source>
        <translation>窗口：</translation>
    </message>
    <message>
        <source>Overlay</source>
        <translation>叠加</translation>
    </message>
    <message>
        <source>One chart with a value axis per unit instead of stacked charts</source>
        <translation>一张图表，每种单位一条数值轴，而不是上下排列的多张图表</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <source>Fit the value axes to the data (Ctrl+wheel scales them by hand)</source>
        <translation>使数值轴适应数据（Ctrl+滚轮手动缩放）</translation>
    </message>
    <message>
        <source>Visible range…</source>
        <translation>可见范围…</translation>
    </message>
    <message>
        <source>Everything recorded…</source>
        <translation>全部记录…</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>导出 CSV</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>导出 PNG…</translation>
    </message>
    <message>
        <source>Signals:</source>
        <translation>信号：</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>导出 PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>Layout</source>
        <translation>布局</translation>
    </message>
    <message>
        <source>Wide: one row per poll round</source>
        <translation>宽格式：每轮轮询一行</translation>
    </message>
    <message>
        <source>time_s, then a column per drive and signal (id3_speed_dps, ...)</source>
        <translation>先是 time_s，然后每个驱动的每个信号各一列（id3_speed_dps 等）</translation>
    </message>
    <message>
        <source>Long: one row per drive and poll round</source>
        <translation>长格式：每个驱动每轮轮询一行</translation>
    </message>
    <message>
        <source>time_s, id, then a column per signal</source>
        <translation>先是 time_s 和驱动 ID，然后每个信号各一列</translation>
    </message>
    <message>
        <source>What a master commanded, beside what the drive replied (the other master&apos;s commands on a listen-only link)</source>
        <translation>主站下发的指令，与驱动器的应答并列（只听模式下为另一主站的指令）</translation>
    </message>
    <message>
        <source>Commanded</source>
        <translation>指令值</translation>
    </message>
    <message>
        <source>Commanded (%1)</source>
        <translation>指令值（%1）</translation>
    </message>
</context>
<context>
    <name>lk::ui::PollRateControl</name>
    <message>
        <source>Max</source>
        <translation>最快</translation>
    </message>
    <message>
        <source>Poll rate:</source>
        <translation>轮询频率：</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Poll as fast as the bus allows</source>
        <translation>以总线允许的最快速度轮询</translation>
    </message>
    <message>
        <source>Bus limit: unknown</source>
        <translation>总线上限：未知</translation>
    </message>
    <message>
        <source>Bus limit: %1 transactions/s, %2 Hz per cycle</source>
        <translation>总线上限：%1 次通信/s，每轮 %2 Hz</translation>
    </message>
    <message>
        <source>(request above the limit: the bus caps it)</source>
        <translation>（请求值超过上限：由总线限制）</translation>
    </message>
    <message>
        <source>One cycle polls every plotted motor once; the limit follows from the baud, the frame sizes and the turnaround the drives showed.</source>
        <translation>一个周期对每台绘图中的电机各轮询一次；上限由波特率、帧长度和驱动器实测的应答间隔决定。</translation>
    </message>
</context>
<context>
    <name>lk::ui::PortAccessDialog</name>
    <message>
        <source>No permission for %1</source>
        <translation>没有 %1 的访问权限</translation>
    </message>
    <message>
        <source>lkstudio may not open %1: your user is not in the group that owns serial ports.</source>
        <translation>lkstudio 无法打开 %1：您的用户不在拥有串口的用户组中。</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Copied</source>
        <translation>已复制</translation>
    </message>
</context>
<context>
    <name>lk::ui::Readout</name>
    <message>
        <source>No update for over a second</source>
        <translation>超过一秒未更新</translation>
    </message>
</context>
<context>
    <name>lk::ui::RecordingController</name>
    <message numerus="yes">
        <source>Save the last %n minute(s)</source>
        <translation>
            <numerusform>保存最近 %n 分钟</numerusform>
        </translation>
    </message>
    <message>
        <source>Write what the black box holds to %1</source>
        <translation>将黑匣子中的内容写入 %1</translation>
    </message>
    <message>
        <source>&amp;Open recording…</source>
        <translation>打开记录文件(&amp;O)…</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>打开记录文件</translation>
    </message>
    <message>
        <source>LK Servo Studio recordings (*.lkrec);;All files (*)</source>
        <translation>LK Servo Studio 记录文件 (*.lkrec);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Cannot open the recording %1: %2</source>
        <translation>无法打开记录文件 %1：%2</translation>
    </message>
    <message>
        <source>Replaying %1: %2, recorded %3. Nothing is sent while a recording plays.</source>
        <translation>正在回放 %1：%2，记录于 %3。回放期间不会发送任何数据。</translation>
    </message>
    <message>
        <source>It plays up to the damage: %1</source>
        <translation>只能回放到损坏处：%1</translation>
    </message>
    <message>
        <source>the emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>a new drive fault flag</source>
        <translation>新的驱动器故障标志</translation>
    </message>
    <message>
        <source>the link loss</source>
        <translation>链路丢失</translation>
    </message>
    <message>
        <source>a burst of timeouts</source>
        <translation>连续超时</translation>
    </message>
    <message>
        <source>your request</source>
        <translation>您的请求</translation>
    </message>
    <message numerus="yes">
        <source>Black box saved after %1: the last %n minute(s) of the link are in %2</source>
        <translation>
            <numerusform>因%1已保存黑匣子：链路最近 %n 分钟的数据位于 %2</numerusform>
        </translation>
    </message>
    <message>
        <source>The black box could not be saved after %1: %2</source>
        <translation>因%1保存黑匣子失败：%2</translation>
    </message>
    <message>
        <source>Black box &amp;length…</source>
        <translation>黑匣子时长(&amp;L)…</translation>
    </message>
    <message>
        <source>Black box length</source>
        <translation>黑匣子时长</translation>
    </message>
    <message>
        <source>Minutes of the link the black box keeps (it also keeps at most 128 MB):</source>
        <translation>黑匣子保留链路的分钟数（同时最多保留 128 MB）：</translation>
    </message>
    <message>
        <source>The black box length (recording/blackBoxMinutes) must be %1..%2 minutes, not %3: it stays %4.</source>
        <translation>黑匣子时长（recording/blackBoxMinutes）必须为 %1..%2 分钟，不能是 %3：仍为 %4。</translation>
    </message>
    <message>
        <source>Export recording as &amp;candump log…</source>
        <translation>将录制导出为 &amp;candump 日志…</translation>
    </message>
    <message>
        <source>Write a recording made on CAN as a candump -L log, which can-utils, python-can and SavvyCAN read</source>
        <translation>将在 CAN 上录制的内容写成 candump -L 日志，can-utils、python-can 和 SavvyCAN 均可读取</translation>
    </message>
    <message>
        <source>Export recording as candump log</source>
        <translation>将录制导出为 candump 日志</translation>
    </message>
    <message>
        <source>candump logs (*.log);;All files (*)</source>
        <translation>candump 日志 (*.log);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Cannot export %1: %2</source>
        <translation>无法导出 %1：%2</translation>
    </message>
    <message>
        <source>%1 was recorded on %2, not on CAN: a candump log holds CAN frames only.</source>
        <translation>%1 录制于 %2，而非 CAN 总线：candump 日志只能保存 CAN 帧。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) written to %1 as a candump log.</source>
        <translation>
            <numerusform>已将 %n 帧以 candump 日志写入 %1。</numerusform>
        </translation>
    </message>
    <message>
        <source>The recording is damaged: it was exported up to the damage (%1).</source>
        <translation>录制文件已损坏：已导出损坏处之前的内容（%1）。</translation>
    </message>
</context>
<context>
    <name>lk::ui::ReplayBar</name>
    <message>
        <source>Replay</source>
        <translation>回放</translation>
    </message>
    <message>
        <source>Replay speed; idle gaps longer than a second are shortened</source>
        <translation>回放速度；超过一秒的空闲间隔会被缩短</translation>
    </message>
    <message>
        <source>Load all</source>
        <translation>全部载入</translation>
    </message>
    <message>
        <source>Read the rest of the recording at once: the plots show all of it</source>
        <translation>一次读取记录的其余部分：曲线图显示全部内容</translation>
    </message>
    <message>
        <source>Close recording</source>
        <translation>关闭记录文件</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 / %2</translation>
    </message>
</context>
<context>
    <name>lk::ui::ScanControls</name>
    <message>
        <source>Try every baud</source>
        <translation>尝试所有波特率</translation>
    </message>
    <message>
        <source>Scan the range at each of the ten bauds (slower): for drives whose baud is unknown</source>
        <translation>在十种波特率下逐一扫描该范围（较慢）：用于不知道波特率的驱动</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>扫描</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>IDs</source>
        <translation>ID</translation>
    </message>
    <message numerus="yes">
        <source>ID %1 at %2 baud · %n drive(s) found · about %3 left</source>
        <translation>
            <numerusform>ID %1，%2 波特 · 已找到 %n 个驱动 · 约剩 %3</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Scan cancelled after %1: %n drive(s) found</source>
        <translation>
            <numerusform>扫描在 %1 后取消：已找到 %n 个驱动</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan stopped: %1</source>
        <translation>扫描已停止：%1</translation>
    </message>
    <message numerus="yes">
        <source>Scan done in %1: %n drive(s) found</source>
        <translation>
            <numerusform>扫描完成，用时 %1：已找到 %n 个驱动</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan takes about %1 at %2 baud</source>
        <translation>在 %2 波特率下扫描约需 %1</translation>
    </message>
    <message numerus="yes">
        <source>ID %1 at %2 · %n drive(s) found · about %3 left</source>
        <translation>
            <numerusform>ID %1，%2 · 已找到 %n 个驱动器 · 约剩 %3</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan takes about %1 at %2</source>
        <translation>在 %2 下扫描约需 %1</translation>
    </message>
</context>
<context>
    <name>lk::ui::SerialGroupAdvice</name>
    <message>
        <source>On %1 serial ports belong to the group %2. Add yourself to it with the command below, then log out and back in (or restart) so that the new group applies.</source>
        <translation>在 %1 上，串口属于用户组 %2。用下面的命令把自己加入该组，然后注销并重新登录（或重启），新的用户组才会生效。</translation>
    </message>
    <message>
        <source>Serial ports usually belong to the group %1 (uucp on Arch-like systems; ls -l on the port shows its group). Add yourself to it with the command below, then log out and back in (or restart) so that the new group applies.</source>
        <translation>串口通常属于用户组 %1（Arch 类系统上为 uucp；对端口执行 ls -l 可看到其用户组）。用下面的命令把自己加入该组，然后注销并重新登录（或重启），新的用户组才会生效。</translation>
    </message>
</context>
<context>
    <name>lk::ui::SeriesChooser</name>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>No model reply (0x12) told this drive&apos;s series. MS drives report power where MF, MG and MH report torque current: choose it so that the values are decoded right. Remembered for this port and ID.</source>
        <translation>没有型号应答（0x12）告知此驱动器的系列。MS 驱动器报告功率，而 MF、MG 和 MH 报告转矩电流：请选择系列，以便正确解码数值。按此端口和 ID 记住。</translation>
    </message>
    <message>
        <source>Series of drive %1:</source>
        <translation>驱动器 %1 的系列：</translation>
    </message>
    <message>
        <source>Gear ratio:</source>
        <translation>减速比：</translation>
    </message>
    <message>
        <source>No model name told this drive&apos;s gearbox (CAN drives have no model read): angles and speeds at the output shaft use this ratio. Remembered for this drive.</source>
        <translation>没有型号名称说明该驱动的减速箱（CAN 驱动无法读取型号）：输出轴上的角度和速度使用此减速比。按驱动记住。</translation>
    </message>
    <message>
        <source>CAN generation:</source>
        <translation>CAN 代次：</translation>
    </message>
    <message>
        <source>old (0x140 replies)</source>
        <translation>旧版（0x140 应答）</translation>
    </message>
    <message>
        <source>V2.36</source>
        <translation>V2.36</translation>
    </message>
    <message>
        <source>CAN has no model read: the reply ID and the 0x9A layout tell most drives&apos; generation. Choose it where they do not (a V2.36 drive that answers on 0x140+ID); values and the commands offered follow it. Remembered for this port and ID.</source>
        <translation>CAN 没有型号读取：大多数驱动器的代次由应答 ID 和 0x9A 的布局判断。无法判断时请在此选择（例如在 0x140+ID 上应答的 V2.36 驱动器）；数值解码和可用命令都随之而定。按此端口和 ID 记住。</translation>
    </message>
</context>
<context>
    <name>lk::ui::SetpointPanel</name>
    <message>
        <source>Setpoint generator</source>
        <translation>设定值发生器</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>阶跃</translation>
    </message>
    <message>
        <source>Square</source>
        <translation>方波</translation>
    </message>
    <message>
        <source>Sine</source>
        <translation>正弦波</translation>
    </message>
    <message>
        <source>Ramp (triangle)</source>
        <translation>斜坡（三角波）</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Commands per second (at most %1; skipped while the bus is behind)</source>
        <translation>每秒命令数（最多 %1；总线跟不上时跳过）</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Stop generator</source>
        <translation>停止发生器</translation>
    </message>
    <message>
        <source>Waveform:</source>
        <translation>波形：</translation>
    </message>
    <message>
        <source>Drives:</source>
        <translation>控制量：</translation>
    </message>
    <message>
        <source>Amplitude:</source>
        <translation>幅值：</translation>
    </message>
    <message>
        <source>Offset:</source>
        <translation>偏置：</translation>
    </message>
    <message>
        <source>Period:</source>
        <translation>周期：</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>频率：</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Position (multi-turn)</source>
        <translation>位置（多圈）</translation>
    </message>
    <message>
        <source>Torque current</source>
        <translation>转矩电流</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> dps</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source> A</source>
        <translation> A</translation>
    </message>
    <message>
        <source>Running: Stop, Motor Off or Esc ends it.</source>
        <translation>运行中：电机停止、电机关闭或 Esc 可结束。</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>已停止。</translation>
    </message>
</context>
<context>
    <name>lk::ui::ShortcutsDialog</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <source>Emergency stop: Motor Off to every drive, from anywhere</source>
        <translation>急停：在任何地方向每个驱动发送电机关闭</translation>
    </message>
</context>
<context>
    <name>lk::ui::SoftLimitsEditor</name>
    <message>
        <source>Soft limits</source>
        <translation>软限位</translation>
    </message>
    <message>
        <source> A</source>
        <translation> A</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> dps</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Angle at least</source>
        <translation>角度不小于</translation>
    </message>
    <message>
        <source>Angle at most</source>
        <translation>角度不大于</translation>
    </message>
    <message>
        <source>Step at most</source>
        <translation>步长不大于</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>Torque current at most:</source>
        <translation>转矩电流不大于：</translation>
    </message>
    <message>
        <source>Open-loop power at most:</source>
        <translation>开环功率不大于：</translation>
    </message>
    <message>
        <source>Speed at most:</source>
        <translation>速度不大于：</translation>
    </message>
    <message>
        <source>The lowest angle must not be above the highest.</source>
        <translation>最小角度不能大于最大角度。</translation>
    </message>
    <message>
        <source>Bounds speed commands, jog and the max speed of every position move</source>
        <translation>限制速度命令、点动以及每次位置运动的最大速度</translation>
    </message>
    <message>
        <source>Checked before every command, after the %1 series limits (%2 A, %3 dps; the default speed limit is that top speed). Angles and speeds are rotor values; a position move goes at most one output turn.</source>
        <translation>每条命令发送前检查，在 %1 系列限值（%2 A，%3 dps；默认速度限值即该最高速度）之后。角度和速度均为转子值；每次位置运动最多为输出轴一圈。</translation>
    </message>
    <message>
        <source>The series is unknown: torque and open loop stay refused until a scan; the default speed limit is %1 dps, the slowest series&apos; top speed.</source>
        <translation>系列未知：扫描前转矩和开环控制保持拒绝；默认速度限值为 %1 dps，即最慢系列的最高速度。</translation>
    </message>
</context>
<context>
    <name>lk::ui::SpeedWatchReport</name>
    <message>
        <source>open loop (0xA0)</source>
        <translation>开环（0xA0）</translation>
    </message>
    <message>
        <source>torque (0xA1)</source>
        <translation>转矩（0xA1）</translation>
    </message>
    <message>
        <source>your speed limit %1 dps</source>
        <translation>您的速度限制 %1 dps</translation>
    </message>
    <message>
        <source>the series&apos; top speed %1 dps (no soft limit given)</source>
        <translation>该系列的最高速度 %1 dps（未设置软限制）</translation>
    </message>
    <message>
        <source>Drive %1 reached %2 dps under %3, past %4 (stopped above %5 dps).</source>
        <translation>驱动器 %1 在%3下达到 %2 dps，超过了%4（高于 %5 dps 即停止）。</translation>
    </message>
    <message>
        <source>Motor Stop (0x81) sent and acknowledged %1 ms after that reading; the drive coasts to a stop.</source>
        <translation>该读数后 %1 ms 已发送并确认电机停止（0x81）；驱动器将惯性滑行至停止。</translation>
    </message>
    <message>
        <source>Motor Stop (0x81) sent but not acknowledged (%1): the drive may still be turning; the watch stops it again while it reads too fast. Press Esc to stop every drive.</source>
        <translation>已发送电机停止（0x81）但未确认（%1）：驱动器可能仍在转动；只要读数过快，监视会再次停止它。按 Esc 停止所有驱动器。</translation>
    </message>
    <message>
        <source>Stopped by the speed watch at %1: %2</source>
        <translation>已于 %1 被速度监视停止：%2</translation>
    </message>
    <message>
        <source>Speed watch:</source>
        <translation>速度监视：</translation>
    </message>
    <message>
        <source>Read the drive&apos;s own Max Speed (ParamID 0x9A) and set it to %1 dps (RAM)</source>
        <translation>读取驱动器自身的最大速度（ParamID 0x9A）并设为 %1 dps（RAM）</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s Max Speed…</source>
        <translation>正在读取驱动器的最大速度…</translation>
    </message>
    <message>
        <source>The drive&apos;s Max Speed could not be read (%1): nothing was written.</source>
        <translation>无法读取驱动器的最大速度（%1）：未写入任何内容。</translation>
    </message>
    <message>
        <source>unexpected reply</source>
        <translation>意外的应答</translation>
    </message>
    <message>
        <source>The drive&apos;s own Max Speed is %1 dps, not above your limit: nothing was written.</source>
        <translation>驱动器自身的最大速度为 %1 dps，不高于您的限制：未写入任何内容。</translation>
    </message>
    <message>
        <source>The drive&apos;s Max Speed read %1 dps.</source>
        <translation>驱动器的最大速度读数为 %1 dps。</translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>正在写入…</translation>
    </message>
    <message>
        <source>the drive refused the write</source>
        <translation>驱动器拒绝了写入</translation>
    </message>
    <message>
        <source>no confirmation (%1)</source>
        <translation>无确认（%1）</translation>
    </message>
    <message>
        <source>Max Speed not confirmed: %1; nothing was verified.</source>
        <translation>最大速度未确认：%1；未验证任何内容。</translation>
    </message>
    <message>
        <source>Max Speed written (the drive confirmed the RAM write), but the read-back got no answer: not verified.</source>
        <translation>最大速度已写入（驱动器确认了 RAM 写入），但回读无应答：未验证。</translation>
    </message>
    <message>
        <source>Max Speed set: the drive reads back %1 dps (RAM: until it is powered off). It bounds the drive&apos;s speed and position commands; whether it also bounds torque and open loop is not documented, so the speed watch stays on.</source>
        <translation>最大速度已设置：驱动器回读为 %1 dps（RAM：断电前有效）。它限制驱动器的速度和位置指令；文档未说明它是否也限制转矩和开环，因此速度监视保持开启。</translation>
    </message>
    <message>
        <source>Max Speed written, but the drive reads back %1 dps instead of %2 dps.</source>
        <translation>最大速度已写入，但驱动器回读为 %1 dps，而非 %2 dps。</translation>
    </message>
</context>
<context>
    <name>lk::ui::StartupOptions</name>
    <message>
        <source>Open the serial port DEV (e.g. /dev/ttyUSB0, COM3).</source>
        <translation>打开串口 DEV（例如 /dev/ttyUSB0、COM3）。</translation>
    </message>
    <message>
        <source>Baud rate: 9600 ... 4000000 (default 115200).</source>
        <translation>波特率：9600 ... 4000000（默认 115200）。</translation>
    </message>
    <message>
        <source>Open the built-in simulated bus with these drives, e.g. 1:MF,2:MG,3:MS,4:MH or 5:MG5010E-i36.</source>
        <translation>打开内置模拟总线并使用这些驱动，例如 1:MF,2:MG,3:MS,4:MH 或 5:MG5010E-i36。</translation>
    </message>
    <message>
        <source>Inject faults into the simulated bus, e.g. corrupt=0.01,garbage=0.01,drop=0.005 (also length=P, delay=P, delay_ms=N, silent=ID, seed=N).</source>
        <translation>向模拟总线注入故障，例如 corrupt=0.01,garbage=0.01,drop=0.005（还有 length=P、delay=P、delay_ms=N、silent=ID、seed=N）。</translation>
    </message>
    <message>
        <source>Read and write settings in FILE (INI) instead of the user&apos;s settings.</source>
        <translation>在 FILE (INI) 中读写设置，而不是使用用户的设置。</translation>
    </message>
    <message>
        <source>Do not scan the bus after connecting.</source>
        <translation>连接后不扫描总线。</translation>
    </message>
    <message>
        <source>Select drive ID once it is found.</source>
        <translation>找到驱动 ID 后选中它。</translation>
    </message>
    <message>
        <source>Unexpected argument: %1</source>
        <translation>多余的参数：%1</translation>
    </message>
    <message>
        <source>--port and --sim exclude each other: pick one bus.</source>
        <translation>--port 和 --sim 不能同时使用：请选择一条总线。</translation>
    </message>
    <message>
        <source>--baud %1 is not an LK baud (9600, 19200, 38400, 57600, 115200, 230400, 460800, 1000000, 2000000, 4000000).</source>
        <translation>--baud %1 不是 LK 波特率（9600、19200、38400、57600、115200、230400、460800、1000000、2000000、4000000）。</translation>
    </message>
    <message>
        <source>--sim: %1</source>
        <translation>--sim：%1</translation>
    </message>
    <message>
        <source>--sim-faults works on the simulated bus only, not with --port.</source>
        <translation>--sim-faults 只能用于模拟总线，不能与 --port 同用。</translation>
    </message>
    <message>
        <source>--sim-faults: %1</source>
        <translation>--sim-faults：%1</translation>
    </message>
    <message>
        <source>--sim-motion moves simulated drives only; it cannot go with --port.</source>
        <translation>--sim-motion 只移动模拟驱动；不能与 --port 同用。</translation>
    </message>
    <message>
        <source>--select takes an ID from 1 to 32.</source>
        <translation>--select 需要 1 到 32 的 ID。</translation>
    </message>
    <message>
        <source>--sim-low-voltage takes a simulated drive&apos;s ID from 1 to 32.</source>
        <translation>--sim-low-voltage 需要 1 到 32 的模拟驱动 ID。</translation>
    </message>
    <message>
        <source>--window-size takes WIDTHxHEIGHT, e.g. 1600x1000.</source>
        <translation>--window-size 需要 宽x高，例如 1600x1000。</translation>
    </message>
    <message>
        <source>--palette takes dark or light.</source>
        <translation>--palette 需要 dark 或 light。</translation>
    </message>
    <message>
        <source>--screenshot-delay-ms takes a number of milliseconds.</source>
        <translation>--screenshot-delay-ms 需要毫秒数。</translation>
    </message>
    <message>
        <source>Start on a view: dashboard, overview, plots, traffic, tuning, control, encoder, info.</source>
        <translation>启动时显示的视图：dashboard、overview、plots、traffic、tuning、control、encoder、info。</translation>
    </message>
    <message>
        <source>--cycle-views takes a period of at least 100 ms.</source>
        <translation>--cycle-views 需要至少 100 毫秒的周期。</translation>
    </message>
    <message>
        <source>--settings %1: %2</source>
        <translation>--settings %1：%2</translation>
    </message>
    <message>
        <source>A recording (.lkrec) to replay instead of connecting.</source>
        <translation>要回放的记录文件（.lkrec），代替连接总线。</translation>
    </message>
    <message>
        <source>Listen only: watch a bus another controller runs and transmit nothing, not even an emergency stop.</source>
        <translation>仅监听：观察由其他控制器运行的总线，不发送任何数据，连急停也不发送。</translation>
    </message>
    <message>
        <source>Open the bus as its master (the default unless the last connection listened).</source>
        <translation>作为主站打开总线（默认如此，除非上次连接为仅监听）。</translation>
    </message>
    <message>
        <source>--listen and --no-listen exclude each other.</source>
        <translation>--listen 与 --no-listen 不能同时使用。</translation>
    </message>
    <message>
        <source>CAN bit rate: 1000000, 500000, 250000, 125000 or 100000 (default 1000000).</source>
        <translation>CAN 比特率：1000000、500000、250000、125000 或 100000（默认 1000000）。</translation>
    </message>
    <message>
        <source>LK Servo Studio: connect, scan, watch, plot and diagnose LK-TECH servo drives on an RS485 or CAN bus. With no options it opens the last port used if it is plugged in, else the built-in simulated bus.</source>
        <translation>LK Servo Studio：连接、扫描、监视、绘图并诊断 RS485 或 CAN 总线上的 LK-TECH 伺服驱动。不带选项时，若上次使用的端口已插入则打开它，否则打开内置的模拟总线。</translation>
    </message>
    <message>
        <source>--can, --port and --sim exclude each other: pick one bus.</source>
        <translation>--can、--port 和 --sim 互斥：请只选一条总线。</translation>
    </message>
    <message>
        <source>--can takes PLUGIN:INTERFACE, e.g. socketcan:can0 (found &quot;%1&quot;).</source>
        <translation>--can 的参数为 插件:接口，例如 socketcan:can0（实际为“%1”）。</translation>
    </message>
    <message>
        <source>--bitrate is the bit rate of a CAN bus; it cannot go with --port or --sim (their rate is --baud).</source>
        <translation>--bitrate 是 CAN 总线的比特率，不能与 --port 或 --sim 同用（它们的速率用 --baud）。</translation>
    </message>
    <message>
        <source>--bitrate %1 is not a CAN bit rate of LK drives (1000000, 500000, 250000, 125000, 100000).</source>
        <translation>--bitrate %1 不是 LK 驱动的 CAN 比特率（1000000、500000、250000、125000、100000）。</translation>
    </message>
    <message>
        <source>Open a CAN interface through a Qt SerialBus plugin, e.g. socketcan:can0 (see the README, &quot;Drives on CAN&quot;); &quot;sim&quot;: the built-in simulated bus on CAN (with --sim for its drives).</source>
        <translation>通过 Qt SerialBus 插件打开 CAN 接口，例如 socketcan:can0（见 README“CAN 上的驱动器”）；“sim”：内置的 CAN 模拟总线（用 --sim 指定其驱动器）。</translation>
    </message>
    <message>
        <source>--can sim is the simulated bus: it cannot go with --port.</source>
        <translation>--can sim 是模拟总线：不能与 --port 同用。</translation>
    </message>
</context>
<context>
    <name>lk::ui::StatisticsView</name>
    <message>
        <source>Bus statistics</source>
        <translation>总线统计</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>Transactions/s</source>
        <translation>通信次数/s</translation>
    </message>
    <message>
        <source>Latency min / median / max</source>
        <translation>延迟 最小 / 中位 / 最大</translation>
    </message>
    <message>
        <source>Requests / replies</source>
        <translation>请求 / 回复</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>超时</translation>
    </message>
    <message>
        <source>Retries</source>
        <translation>重试</translation>
    </message>
    <message>
        <source>Checksum errors</source>
        <translation>校验错误</translation>
    </message>
    <message>
        <source>Other frame errors</source>
        <translation>其他帧错误</translation>
    </message>
    <message>
        <source>Garbage bytes</source>
        <translation>无效字节</translation>
    </message>
    <message>
        <source>Polling is off.</source>
        <translation>轮询已关闭。</translation>
    </message>
    <message>
        <source>%1 requested</source>
        <translation>请求 %1</translation>
    </message>
    <message>
        <source>as fast as the bus allows</source>
        <translation>以总线允许的最快速度</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>驱动 %1</translation>
    </message>
    <message>
        <source>Late replies (after their timeout)</source>
        <translation>迟到的回复（超时之后）</translation>
    </message>
    <message>
        <source>Unexpected frames</source>
        <translation>意外的帧</translation>
    </message>
    <message>
        <source>%1 ms turnaround, measured</source>
        <translation>应答间隔 %1 ms，实测</translation>
    </message>
    <message>
        <source>%1 ms turnaround, assumed until replies are measured</source>
        <translation>应答间隔 %1 ms，测得应答之前为假定值</translation>
    </message>
    <message>
        <source>Polling: %1 transactions/s achieved (%2); bus limit %3/s at %4 baud (%5).</source>
        <translation>轮询：实际 %1 次事务/秒（%2）；总线上限 %3 次/秒，波特率 %4（%5）。</translation>
    </message>
    <message>
        <source>Silent IDs probed (scan, stop)</source>
        <translation>探测无应答的 ID（扫描、急停）</translation>
    </message>
    <message>
        <source>Bus statistics: the other master (listen-only)</source>
        <translation>总线统计：另一个主站（仅监听）</translation>
    </message>
    <message>
        <source>Bus statistics: the recording (replay)</source>
        <translation>总线统计：记录文件（回放）</translation>
    </message>
</context>
<context>
    <name>lk::ui::StatusSummary</name>
    <message>
        <source>SIMULATED</source>
        <translation>模拟</translation>
    </message>
    <message>
        <source>The drives are simulated: nothing here moves a real motor</source>
        <translation>驱动是模拟的：这里的操作不会转动真实电机</translation>
    </message>
    <message>
        <source>%1 tx/s</source>
        <translation>%1 次通信/s</translation>
    </message>
    <message>
        <source>(limit %1)</source>
        <translation>（上限 %1）</translation>
    </message>
    <message>
        <source>latency %1 ms</source>
        <translation>延迟 %1 ms</translation>
    </message>
    <message>
        <source>%1 timeouts</source>
        <translation>%1 次超时</translation>
    </message>
    <message>
        <source>%1 checksum errors</source>
        <translation>%1 次校验错误</translation>
    </message>
</context>
<context>
    <name>lk::ui::StepOverlayChart</name>
    <message>
        <source>Time from the step (s)</source>
        <translation>距阶跃的时间 (s)</translation>
    </message>
    <message>
        <source>Power (rel.)</source>
        <translation>功率（相对值）</translation>
    </message>
    <message>
        <source>iq (A)</source>
        <translation>iq (A)</translation>
    </message>
    <message>
        <source>Speed (dps)</source>
        <translation>速度 (dps)</translation>
    </message>
    <message>
        <source>Angle (°)</source>
        <translation>角度 (°)</translation>
    </message>
    <message>
        <source>Reset zoom</source>
        <translation>重置缩放</translation>
    </message>
    <message>
        <source>Show every sample again after zooming or panning</source>
        <translation>缩放或平移后重新显示全部采样</translation>
    </message>
    <message>
        <source>Hover for values · wheel: zoom · drag: pan · Shift+drag: select a range</source>
        <translation>悬停查看数值 · 滚轮：缩放 · 拖动：平移 · Shift+拖动：选择范围</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>lk::ui::StepRunFileText</name>
    <message>
        <source>an integer in %1..%2</source>
        <translation>%1..%2 之间的整数</translation>
    </message>
    <message>
        <source>a number in %1..%2</source>
        <translation>%1..%2 之间的数值</translation>
    </message>
    <message>
        <source>text</source>
        <translation>文本</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>列表</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is larger than any run file (%2 bytes at most)</source>
        <translation>%1 超过了测试文件的最大长度（最多 %2 字节）</translation>
    </message>
    <message>
        <source>%1 is not JSON (%2, at byte %3)</source>
        <translation>%1 不是 JSON（%2，位于第 %3 字节）</translation>
    </message>
    <message>
        <source>%1 does not hold a JSON object</source>
        <translation>%1 不包含 JSON 对象</translation>
    </message>
    <message>
        <source>%1 is not a step-run file (format %2)</source>
        <translation>%1 不是阶跃测试文件（格式为 %2）</translation>
    </message>
    <message>
        <source>%1 was written by a newer release (version %2; this one reads up to %3)</source>
        <translation>%1 由更新的版本写入（版本 %2；本版本最多读取 %3）</translation>
    </message>
    <message>
        <source>%1 lacks %2</source>
        <translation>%1 缺少 %2</translation>
    </message>
    <message>
        <source>%1 has a key this format does not have: %2</source>
        <translation>%1 含有本格式没有的键：%2</translation>
    </message>
    <message>
        <source>%1 gives %2 twice</source>
        <translation>%1 中 %2 出现了两次</translation>
    </message>
    <message>
        <source>%1: %2 is %3; it must be %4</source>
        <translation>%1：%2 的值为 %3；应为 %4</translation>
    </message>
    <message>
        <source>%1: %2 holds %3, which means nothing there</source>
        <translation>%1：%2 的值 %3 在此处没有意义</translation>
    </message>
    <message>
        <source>%1: the steps in %2 are not in time order</source>
        <translation>%1：%2 中的阶跃没有按时间顺序排列</translation>
    </message>
    <message>
        <source>%1 names a trace file that cannot be read (%2): %3</source>
        <translation>%1 引用的曲线文件无法读取（%2）：%3</translation>
    </message>
    <message>
        <source>%1, line 1: the header is %2, not time_s,value,effort</source>
        <translation>%1 第 1 行：表头为 %2，而不是 time_s,value,effort</translation>
    </message>
    <message>
        <source>%1, line %2: %3 is not three cells</source>
        <translation>%1 第 %2 行：%3 不是三个单元格</translation>
    </message>
    <message>
        <source>%1, line %2, %3: %4 is not a number</source>
        <translation>%1 第 %2 行，%3：%4 不是数值</translation>
    </message>
    <message>
        <source>%1, line %2: time %3 is not after the line before</source>
        <translation>%1 第 %2 行：时间 %3 不晚于上一行</translation>
    </message>
</context>
<context>
    <name>lk::ui::StepRunList</name>
    <message>
        <source>Run %1</source>
        <translation>测试 %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>lk::ui::StepRunsModel</name>
    <message>
        <source>shown</source>
        <translation>显示</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>%1 periods of %2 s</source>
        <translation>%1 个周期，每半周期 %2 s</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 %2 → %3, %4</source>
        <translation>%1 %2 → %3，%4</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>%1 at %2 Hz</source>
        <translation>%1 个，%2 Hz</translation>
    </message>
    <message>
        <source>Overlay</source>
        <translation>叠加显示</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>驱动</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>测试</translation>
    </message>
    <message>
        <source>Ran at</source>
        <translation>测试时间</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>采样</translation>
    </message>
    <message numerus="yes">
        <source>Best of the %n comparable run(s) shown (same loop and unit).</source>
        <translation>
            <numerusform>所显示的 %n 个可比测试中最佳（相同环路和单位）。</numerusform>
        </translation>
    </message>
    <message>
        <source>Not compared: no other run shown has the same loop and unit.</source>
        <translation>未比较：所显示的其他测试中没有相同环路和单位的。</translation>
    </message>
</context>
<context>
    <name>lk::ui::StepRunsView</name>
    <message>
        <source>Save runs…</source>
        <translation>保存测试…</translation>
    </message>
    <message>
        <source>Load runs…</source>
        <translation>加载测试…</translation>
    </message>
    <message>
        <source>Remove run</source>
        <translation>移除此运行</translation>
    </message>
    <message>
        <source>Clear all</source>
        <translation>全部清除</translation>
    </message>
    <message>
        <source>What do these mean?</source>
        <translation>这些指标是什么意思？</translation>
    </message>
    <message>
        <source>Save step runs</source>
        <translation>保存阶跃测试</translation>
    </message>
    <message>
        <source>Step runs (*.lkruns.json)</source>
        <translation>阶跃测试 (*.lkruns.json)</translation>
    </message>
    <message>
        <source>Load step runs</source>
        <translation>加载阶跃测试</translation>
    </message>
    <message>
        <source>No runs yet: run a step test, change a gain, write it to RAM and repeat the test to compare.</source>
        <translation>尚无测试：先做一次阶跃测试，修改参数并写入 RAM，再重复测试进行比较。</translation>
    </message>
    <message numerus="yes">
        <source>%n run(s) of the other loop hidden: the overlay shows one loop at a time.</source>
        <translation>
            <numerusform>已隐藏 %n 个另一环的测试：叠加图一次只显示一个环。</numerusform>
        </translation>
    </message>
    <message>
        <source>Runs aligned on their step (0 s); dashed: each run&apos;s target. Best values of the runs shown are bold.</source>
        <translation>各次测试按阶跃时刻（0 s）对齐；虚线为各自的目标值。所显示测试中的最佳值以粗体标出。</translation>
    </message>
    <message>
        <source>Step response metrics</source>
        <translation>阶跃响应指标</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n run(s) to %1.</source>
        <translation>
            <numerusform>已将 %n 个测试保存到 %1。</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not save: %1</source>
        <translation>无法保存：%1</translation>
    </message>
    <message>
        <source>Could not load: %1. Nothing was added.</source>
        <translation>无法加载：%1。未添加任何测试。</translation>
    </message>
    <message numerus="yes">
        <source>Added %n run(s) from %1.</source>
        <translation>
            <numerusform>已从 %1 添加 %n 个测试。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::StepTestPanel</name>
    <message>
        <source>Step test</source>
        <translation>阶跃测试</translation>
    </message>
    <message>
        <source>Test step</source>
        <translation>阶跃测试</translation>
    </message>
    <message>
        <source>Repeat last test</source>
        <translation>重复上次测试</translation>
    </message>
    <message>
        <source>Run the last test again with the gains the drive holds now.</source>
        <translation>用驱动当前的参数再次执行上次的测试。</translation>
    </message>
    <message>
        <source>Steps the speed or position loop of the selected drive and measures the response. Every setpoint is checked against the soft limits (Control view) before anything moves; Esc stops the motors.</source>
        <translation>对所选驱动的速度环或位置环施加阶跃并测量响应。任何运动之前，每个设定值都先按软限位（控制页）检查；按 Esc 停止电机。</translation>
    </message>
    <message>
        <source>Speed loop</source>
        <translation>速度环</translation>
    </message>
    <message>
        <source>Position loop</source>
        <translation>位置环</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>1: one step from FROM to TO. More: a square wave of that many periods, each half held for the duration.</source>
        <translation>1：从起点到终点的单次阶跃。更多：该周期数的方波，每半个周期保持设定的时间。</translation>
    </message>
    <message>
        <source>periods</source>
        <translation>个周期</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>环</translation>
    </message>
    <message>
        <source>From → to</source>
        <translation>起点 → 终点</translation>
    </message>
    <message>
        <source>Each step</source>
        <translation>每步保持</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> dps</translation>
    </message>
    <message>
        <source>Rotor speed. The drive is held at FROM before the step and goes back to FROM after it.</source>
        <translation>转子速度。阶跃前驱动保持在起点速度，阶跃后回到起点速度。</translation>
    </message>
    <message>
        <source>Multi-turn rotor angle. Filled in from where the drive is; each target may be at most one output turn away.</source>
        <translation>转子多圈角度。按驱动当前位置填入；每个目标最多相距输出轴一圈。</translation>
    </message>
    <message>
        <source> Max speed %1 dps.</source>
        <translation> 最大速度 %1 dps。</translation>
    </message>
    <message>
        <source>Testing drive %1: %2 setpoints over %3 s.%4</source>
        <translation>正在测试驱动 %1：%3 s 内发送 %2 个设定值。%4</translation>
    </message>
    <message>
        <source>Nothing was sent: connect and select a drive first.</source>
        <translation>未发送任何命令：请先连接并选择驱动。</translation>
    </message>
    <message>
        <source>Nothing was sent: FROM and TO are equal, there is no step.</source>
        <translation>未发送任何命令：起点与终点相同，没有阶跃。</translation>
    </message>
    <message>
        <source>Nothing was sent: no soft limits are in force.</source>
        <translation>未发送任何命令：没有生效的软限位。</translation>
    </message>
    <message>
        <source>Reading where drive %1 is…</source>
        <translation>正在读取驱动 %1 的当前位置…</translation>
    </message>
    <message>
        <source>Run %1: rise %2, overshoot %3, settling (2 %) %4; %5 samples at %6 Hz. %7</source>
        <translation>测试 %1：上升时间 %2，超调 %3，调节时间（2 %）%4；%5 个采样，%6 Hz。%7</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>未发送任何命令。</translation>
    </message>
    <message>
        <source>The test cannot run as set (%1).</source>
        <translation>按当前设置无法执行测试（%1）。</translation>
    </message>
    <message>
        <source>Drive %1 did not answer: the test stopped.</source>
        <translation>驱动 %1 无应答：测试已停止。</translation>
    </message>
    <message>
        <source>The link went down: the test stopped.</source>
        <translation>连接已断开：测试已停止。</translation>
    </message>
    <message>
        <source>The test was stopped.</source>
        <translation>测试已停止。</translation>
    </message>
    <message>
        <source>Drive %1 was last told to turn at %2 dps and keeps doing so until stopped.</source>
        <translation>驱动 %1 最后收到的命令是以 %2 dps 转动，在停止之前会一直保持。</translation>
    </message>
    <message>
        <source>Drive %1 was last told to stand still (0 dps).</source>
        <translation>驱动 %1 最后收到的命令是静止（0 dps）。</translation>
    </message>
    <message>
        <source>Drive %1 holds (or is moving to) %2°.</source>
        <translation>驱动 %1 保持在（或正在运动到）%2°。</translation>
    </message>
    <message>
        <source>Stop (Esc)</source>
        <translation>停止 (Esc)</translation>
    </message>
    <message>
        <source>Emergency stop: Motor Off to every drive.</source>
        <translation>急停：向所有驱动发送电机关闭。</translation>
    </message>
    <message>
        <source>Run the step test set above on the selected drive.</source>
        <translation>在所选驱动上执行上面设置的阶跃测试。</translation>
    </message>
    <message>
        <source>Refused: %1.</source>
        <translation>已拒绝：%1。</translation>
    </message>
</context>
<context>
    <name>lk::ui::StripChart</name>
    <message>
        <source>ID %1 %2</source>
        <translation>ID %1 %2</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
</context>
<context>
    <name>lk::ui::TelemetryChannel</name>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>counts</source>
        <translation>计数</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <source>Current (A)</source>
        <translation>电流 (A)</translation>
    </message>
    <message>
        <source>Speed (°/s)</source>
        <translation>速度 (°/s)</translation>
    </message>
    <message>
        <source>Encoder (counts)</source>
        <translation>编码器（计数）</translation>
    </message>
    <message>
        <source>Angle (°)</source>
        <translation>角度 (°)</translation>
    </message>
    <message>
        <source>Temperature (°C)</source>
        <translation>温度 (°C)</translation>
    </message>
    <message>
        <source>Voltage (V)</source>
        <translation>电压 (V)</translation>
    </message>
    <message>
        <source>Power (rel.)</source>
        <translation>功率（相对值）</translation>
    </message>
    <message>
        <source>iq / power</source>
        <translation>iq / 功率</translation>
    </message>
    <message>
        <source>Commanded iq / power</source>
        <translation>指令 iq / 功率</translation>
    </message>
</context>
<context>
    <name>lk::ui::TrafficModel</name>
    <message>
        <source>TX</source>
        <translation>发送</translation>
    </message>
    <message>
        <source>RX</source>
        <translation>接收</translation>
    </message>
    <message>
        <source>RX fault</source>
        <translation>接收错误</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>超时</translation>
    </message>
    <message>
        <source>note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>无回复</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>Dir.</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Fields</source>
        <translation>字段</translation>
    </message>
    <message>
        <source>Raw bytes</source>
        <translation>原始字节</translation>
    </message>
    <message>
        <source>ID %1 %2 A</source>
        <translation>ID %1 %2 A</translation>
    </message>
    <message>
        <source>torque current of IDs 1..4: %1</source>
        <translation>ID 1..4 的转矩电流：%1</translation>
    </message>
</context>
<context>
    <name>lk::ui::TrafficPanel</name>
    <message>
        <source>All IDs</source>
        <translation>所有 ID</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>Faults only</source>
        <translation>仅显示故障</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Freeze the log to read it; faults are still counted</source>
        <translation>冻结记录以便阅读；故障仍会计数</translation>
    </message>
    <message>
        <source>Keep recording</source>
        <translation>持续记录</translation>
    </message>
    <message>
        <source>Keep capturing traffic while another view is shown</source>
        <translation>显示其他页面时也继续捕获通信</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <source>Empty the log and counts</source>
        <translation>清空记录和计数</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <source>Save the rows shown as hex text that `lkctl decode -` reads</source>
        <translation>把显示的行保存为 `lkctl decode -` 可读取的十六进制文本</translation>
    </message>
    <message>
        <source>All commands</source>
        <translation>所有命令</translation>
    </message>
    <message>
        <source>TX %1</source>
        <translation>发送 %1</translation>
    </message>
    <message>
        <source>RX %1</source>
        <translation>接收 %1</translation>
    </message>
    <message>
        <source>timeouts %1</source>
        <translation>超时 %1</translation>
    </message>
    <message>
        <source>no frame faults</source>
        <translation>无帧错误</translation>
    </message>
    <message>
        <source>%1 oldest rows dropped</source>
        <translation>已丢弃最早的 %1 行</translation>
    </message>
    <message>
        <source>Export traffic</source>
        <translation>导出通信记录</translation>
    </message>
    <message>
        <source>Traffic log (*.txt);;All files (*)</source>
        <translation>通信记录 (*.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>checksum errors %1</source>
        <translation>校验错误 %1</translation>
    </message>
    <message>
        <source>other frame errors %1</source>
        <translation>其他帧错误 %1</translation>
    </message>
    <message>
        <source>late replies %1</source>
        <translation>迟到应答 %1</translation>
    </message>
    <message>
        <source>unexpected frames %1</source>
        <translation>意外帧 %1</translation>
    </message>
    <message>
        <source>Bus: %1. This log: %2.</source>
        <translation>总线：%1。本日志：%2。</translation>
    </message>
    <message>
        <source>Hide polling</source>
        <translation>隐藏轮询</translation>
    </message>
    <message>
        <source>Hide the state and angle reads of the poll rounds, so that commands (PID writes, stops, setpoints) stand out</source>
        <translation>隐藏轮询中的状态和角度读取，使命令（PID 写入、停止、设定值）更加醒目</translation>
    </message>
    <message>
        <source>candump log (*.log)</source>
        <translation>candump 日志 (*.log)</translation>
    </message>
    <message>
        <source>Traffic log (*.txt)</source>
        <translation>通信记录 (*.txt)</translation>
    </message>
</context>
<context>
    <name>lk::ui::TuningFile</name>
    <message>
        <source>Nothing to save: read the drive&apos;s parameters first.</source>
        <translation>没有可保存的内容：请先读取驱动的参数。</translation>
    </message>
    <message>
        <source>Saved the parameters of drive %1 to %2.</source>
        <translation>已将驱动 %1 的参数保存到 %2。</translation>
    </message>
    <message>
        <source>Could not save: %1</source>
        <translation>无法保存：%1</translation>
    </message>
    <message>
        <source>the file holds the gains of a protocol %1 drive, this drive speaks %2: the gains of the two generations differ in number and range</source>
        <translation>该文件保存的是协议 %1 驱动的参数，而此驱动使用 %2：两个协议版本的参数数量和范围都不同</translation>
    </message>
    <message>
        <source>Could not load %1: %2. Nothing was changed.</source>
        <translation>无法加载 %1：%2。未做任何更改。</translation>
    </message>
    <message>
        <source>Loaded the parameters of drive %1 (%2, firmware %3, saved %4) into the pending edit: nothing is written until you write to RAM or ROM.</source>
        <translation>已把驱动 %1 的参数（%2，固件 %3，保存于 %4）载入待写入区：在写入 RAM 或 ROM 之前不会写入任何值。</translation>
    </message>
    <message>
        <source>unknown motor</source>
        <translation>未知电机</translation>
    </message>
    <message>
        <source>Careful: the file comes from a %1, this drive is a %2.</source>
        <translation>注意：文件来自 %1，而此驱动是 %2。</translation>
    </message>
    <message>
        <source>Loaded the parameters of drive %1 (%2, firmware %3, saved %4) into the pending edit: nothing is written until you write to RAM (this drive has no ROM write).</source>
        <translation>已将驱动器 %1（%2，固件 %3，保存于 %4）的参数载入待写编辑：在写入 RAM 之前不会写入任何内容（该驱动器没有 ROM 写入）。</translation>
    </message>
</context>
<context>
    <name>lk::ui::TuningRunGate</name>
    <message>
        <source>Nothing was sent: connect and select a drive first.</source>
        <translation>未发送任何内容：请先连接并选择驱动器。</translation>
    </message>
    <message>
        <source>Nothing was sent: the gains of drive %1 have not been read on this connection. Read from drive first.</source>
        <translation>未发送任何内容：本次连接中尚未读取驱动 %1 的增益。请先从驱动读取。</translation>
    </message>
    <message>
        <source>Nothing was sent: a step test, read or write of drive %1 is in progress.</source>
        <translation>未发送任何内容：驱动 %1 的阶跃测试、读取或写入正在进行。</translation>
    </message>
    <message>
        <source>Nothing was sent: no soft limits are in force.</source>
        <translation>未发送任何内容：没有生效的软限位。</translation>
    </message>
    <message>
        <source>Refused: an angle range is set for drive %1 (Control view), and this turns the axis for as long as it runs, past any range. Nothing was sent.</source>
        <translation>已拒绝：驱动 %1 设置了角度范围（“控制”视图），而此操作在运行期间会让轴持续转动，超出任何范围。未发送任何内容。</translation>
    </message>
    <message>
        <source>Drive %1 turns at %2 to %3 dps (rotor) for about %4 s: up to %5 rotor turns, %6 turns of the output. Speed limit %7 dps.</source>
        <translation>驱动 %1 将以 %2 到 %3 dps（转子）转动约 %4 秒：转子最多 %5 圈，输出轴 %6 圈。速度限值 %7 dps。</translation>
    </message>
    <message>
        <source>Is the axis of drive %1 free to turn?</source>
        <translation>驱动 %1 的轴可以自由转动吗？</translation>
    </message>
    <message>
        <source>The gains read are written back to RAM at the end; Esc stops the motor at once.</source>
        <translation>结束时读取的增益会写回 RAM；按 Esc 立即停止电机。</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Refused by a soft limit.</source>
        <translation>被软限位拒绝。</translation>
    </message>
    <message>
        <source>Drive %1 did not answer: it stopped.</source>
        <translation>驱动 %1 未应答：已停止。</translation>
    </message>
    <message>
        <source>The link went down: it stopped.</source>
        <translation>链路断开：已停止。</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>已停止。</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>未发送任何内容。</translation>
    </message>
    <message>
        <source>No step was sent.</source>
        <translation>未发送任何阶跃。</translation>
    </message>
    <message>
        <source>Drive %1 did not acknowledge Motor Off: it may still be moving.</source>
        <translation>驱动 %1 未确认“电机关闭”：它可能仍在运动。</translation>
    </message>
    <message>
        <source>Motor Off went to drive %1 and it acknowledged.</source>
        <translation>已向驱动 %1 发送“电机关闭”，驱动已确认。</translation>
    </message>
    <message>
        <source>The gains read before could NOT be written back: read the drive and check them.</source>
        <translation>之前读取的增益未能写回：请读取驱动并检查。</translation>
    </message>
    <message>
        <source>The gains read before are back in RAM.</source>
        <translation>之前读取的增益已写回 RAM。</translation>
    </message>
    <message>
        <source>The gains read are back in RAM; drive %1 holds 0 dps, its motor stays on.</source>
        <translation>读取的增益已写回 RAM；驱动 %1 保持 0 dps，电机仍处于开启状态。</translation>
    </message>
    <message>
        <source>The gains read are back in RAM; drive %1 is back at the speed it had and keeps turning until stopped.</source>
        <translation>读取的增益已写回 RAM；驱动 %1 已回到原来的速度，并将持续转动直到被停止。</translation>
    </message>
    <message>
        <source>The gains read are back in RAM.</source>
        <translation>读取的增益已写回 RAM。</translation>
    </message>
    <message>
        <source>Refused: the position loop&apos;s response needs an angle range for drive %1 (Control view, both ends): its sine stays inside it. Nothing was sent.</source>
        <translation>已拒绝：位置环频率响应需要为驱动器 %1 设置角度范围（控制视图，两端都要设置）：正弦始终保持在该范围内。未发送任何指令。</translation>
    </message>
    <message>
        <source>Drive %1 swings up to %2° (rotor) either side of where it is, at up to %3 dps, for about %4 s, inside the angle range %5° to %6°. Speed limit %7 dps.</source>
        <translation>驱动器 %1 在当前位置两侧各摆动最多 %2°（转子），速度最高 %3 dps，持续约 %4 秒，始终在角度范围 %5° 至 %6° 之内。速度限制 %7 dps。</translation>
    </message>
    <message>
        <source>The gains read are back in RAM; drive %1 holds the angle it started at, its motor stays on.</source>
        <translation>读取的增益已写回 RAM；驱动器 %1 保持在开始时的角度，电机保持开启。</translation>
    </message>
    <message>
        <source>It cannot run as set.</source>
        <translation>按当前设置无法运行。</translation>
    </message>
</context>
<context>
    <name>lk::ui::TuningSetCan236</name>
    <message>
        <source>CAN V2.36 keeps these in RAM only: they are lost at power-off.</source>
        <translation>CAN V2.36 只把这些参数保存在 RAM 中：断电后即丢失。</translation>
    </message>
    <message>
        <source>0..65535, raw gain (CAN V2.36 control parameters 0x0A..0x0C)</source>
        <translation>0..65535，原始增益（CAN V2.36 控制参数 0x0A..0x0C）</translation>
    </message>
    <message>
        <source>Angle loop</source>
        <translation>角度环</translation>
    </message>
    <message>
        <source>Speed loop</source>
        <translation>速度环</translation>
    </message>
    <message>
        <source>Current loop</source>
        <translation>电流环</translation>
    </message>
    <message>
        <source>Input torque limit</source>
        <translation>输入转矩限制</translation>
    </message>
    <message>
        <source> (of 2048)</source>
        <translation>（满量程 2048）</translation>
    </message>
    <message>
        <source>0x1E, iq units, 2048 = full scale (inferred)</source>
        <translation>0x1E，iq 单位，2048 = 满量程（推断）</translation>
    </message>
    <message>
        <source>Input speed limit</source>
        <translation>输入速度限制</translation>
    </message>
    <message>
        <source> dps</source>
        <translation> dps</translation>
    </message>
    <message>
        <source>0x20, 0.01 dps on the wire (inferred)</source>
        <translation>0x20，线上单位 0.01 dps（推断）</translation>
    </message>
    <message>
        <source>Input angle limit</source>
        <translation>输入角度限制</translation>
    </message>
    <message>
        <source> deg</source>
        <translation> °</translation>
    </message>
    <message>
        <source>0x22, 0.01 deg on the wire (inferred)</source>
        <translation>0x22，线上单位 0.01 度（推断）</translation>
    </message>
    <message>
        <source>Input current ramp (unit unknown)</source>
        <translation>输入电流斜率（单位未知）</translation>
    </message>
    <message>
        <source>0x24: the raw number; the CAN V2.36 document gives no unit</source>
        <translation>0x24：原始数值；CAN V2.36 文档未给出单位</translation>
    </message>
    <message>
        <source>Input speed ramp</source>
        <translation>输入速度斜率</translation>
    </message>
    <message>
        <source> dps/s</source>
        <translation> dps/s</translation>
    </message>
    <message>
        <source>0x26, dps/s (inferred)</source>
        <translation>0x26，dps/s（推断）</translation>
    </message>
    <message>
        <source>Control parameters (CAN V2.36)</source>
        <translation>控制参数（CAN V2.36）</translation>
    </message>
    <message>
        <source>Read with 0xC0 and written with 0xC1 to RAM: effective at once, lost at power-off. </source>
        <translation>用 0xC0 读取、用 0xC1 写入 RAM：立即生效，断电丢失。</translation>
    </message>
    <message>
        <source>read_control_param (0xC0) for IDs 0x0A..0x0C and 0x1E..0x26</source>
        <translation>对 ID 0x0A..0x0C 与 0x1E..0x26 发送 read_control_param (0xC0)</translation>
    </message>
    <message>
        <source>Write the changed values: 0xC1, RAM only, lost at power-off; read back.</source>
        <translation>写入改动的值：0xC1，仅 RAM，断电丢失；随后回读。</translation>
    </message>
    <message>
        <source>No ROM on CAN V2.36</source>
        <translation>CAN V2.36 没有 ROM 写入</translation>
    </message>
    <message>
        <source>Written to the RAM of drive %1 (0xC1) and read back with 0xC0: the drive holds what was sent. </source>
        <translation>已写入驱动器 %1 的 RAM（0xC1）并用 0xC0 回读：驱动器保存的与发送的一致。</translation>
    </message>
</context>
<context>
    <name>lk::ui::TuningSetCycle</name>
    <message>
        <source>Could not read drive %1: %2 Editing and writing stay off until every value shown has been read; press Read from drive to try again.</source>
        <translation>无法读取驱动 %1：%2 在显示的全部数值读取成功之前，编辑和写入保持禁用；请按“从驱动读取”重试。</translation>
    </message>
    <message>
        <source>Read from drive %1 at %2.</source>
        <translation>于 %2 从驱动 %1 读取。</translation>
    </message>
    <message>
        <source>Your unsent edit of drive %1 is back in the pending edit; values that differ from the drive are highlighted.</source>
        <translation>驱动 %1 未发送的编辑已放回待写入区；与驱动不同的值以高亮显示。</translation>
    </message>
    <message>
        <source>Nothing was sent: the drive&apos;s values have not all been read on this connection. Read from drive first.</source>
        <translation>未发送任何命令：本次连接中尚未读取驱动的全部数值。请先从驱动读取。</translation>
    </message>
    <message>
        <source>ROM write cancelled: nothing was sent.</source>
        <translation>已取消 ROM 写入：未发送任何命令。</translation>
    </message>
    <message>
        <source>Restore cancelled: nothing was sent.</source>
        <translation>已取消恢复：未发送任何内容。</translation>
    </message>
    <message>
        <source>The drive or the connection changed: nothing was sent.</source>
        <translation>驱动或连接已改变：未发送任何命令。</translation>
    </message>
    <message>
        <source>Nothing was sent: %1</source>
        <translation>未发送任何命令：%1</translation>
    </message>
    <message>
        <source>Writing gains to the ROM of drive %1…</source>
        <translation>正在把 PID 参数写入驱动 %1 的 ROM…</translation>
    </message>
    <message>
        <source>Writing to the RAM of drive %1…</source>
        <translation>正在写入驱动 %1 的 RAM…</translation>
    </message>
    <message>
        <source>The write failed: %1</source>
        <translation>写入失败：%1</translation>
    </message>
    <message>
        <source>Sent to drive %1, but the read-back did not complete (below).</source>
        <translation>已发送到驱动 %1，但回读未完成（见下方）。</translation>
    </message>
    <message>
        <source>Written, but the read-back differs (below).</source>
        <translation>已写入，但回读值不同（见下方）。</translation>
    </message>
    <message>
        <source>RAM gains differ from what was last written to ROM (%1): a power cycle brings back the ROM values.</source>
        <translation>RAM 中的参数与上次写入 ROM 的不同（%1）：断电重启后恢复为 ROM 中的值。</translation>
    </message>
    <message>
        <source>RAM gains were changed in this session and not written to ROM: they are lost at power-off.</source>
        <translation>RAM 中的参数在本次会话中已修改但未写入 ROM：断电后会丢失。</translation>
    </message>
    <message>
        <source>RAM holds the gains last written to ROM in this session.</source>
        <translation>RAM 中是本次会话最后写入 ROM 的参数。</translation>
    </message>
    <message>
        <source>Nothing written to this drive in this session: RAM holds what the drive loaded from ROM at power-on (unless another tool changed it).</source>
        <translation>本次会话未向此驱动写入任何值：RAM 中是驱动上电时从 ROM 载入的值（除非其他工具修改过）。</translation>
    </message>
</context>
<context>
    <name>lk::ui::TuningSetV235</name>
    <message>
        <source>0..65535, raw gain (V2.35 ParamIDs 0x96..0x98)</source>
        <translation>0..65535，原始增益（V2.35 参数 ID 0x96..0x98）</translation>
    </message>
    <message>
        <source>Angle loop</source>
        <translation>角度环</translation>
    </message>
    <message>
        <source>Speed loop</source>
        <translation>速度环</translation>
    </message>
    <message>
        <source>Current loop</source>
        <translation>电流环</translation>
    </message>
    <message>
        <source>PID gains (protocol V2.35)</source>
        <translation>PID 参数（协议 V2.35）</translation>
    </message>
    <message>
        <source>Gains go to RAM (0x42, try: lost at power-off) or ROM (0x44, keep). No acceleration here: V2.35 has no 0x33/0x34, its current and speed ramps are in the drive limits.</source>
        <translation>参数写入 RAM（0x42，试用：断电丢失）或 ROM（0x44，保存）。这里没有加速度：V2.35 没有 0x33/0x34，其电流和速度斜坡位于驱动限值中。</translation>
    </message>
    <message>
        <source>read_param (0x40) for ParamIDs 0x96, 0x97 and 0x98</source>
        <translation>对 参数 ID 0x96、0x97 和 0x98 执行 read_param (0x40)</translation>
    </message>
    <message>
        <source>Try the pending edit: 0x42, lost at power-off; read back.</source>
        <translation>试用待写入的修改：0x42，断电丢失；随后回读。</translation>
    </message>
    <message>
        <source>Keep the gains: 0x44 writes flash (asks first); read back.</source>
        <translation>保存参数：0x44 写入闪存（会先询问）；随后回读。</translation>
    </message>
    <message>
        <source>angle %1/%2/%3, speed %4/%5/%6, current %7/%8/%9 (Kp/Ki/Kd)</source>
        <translation>角度 %1/%2/%3，速度 %4/%5/%6，电流 %7/%8/%9（Kp/Ki/Kd）</translation>
    </message>
    <message>
        <source>Write gains to ROM</source>
        <translation>写入 PID 参数到 ROM</translation>
    </message>
    <message>
        <source>Write these PID gains to the ROM of drive %1?
%2</source>
        <translation>将这些 PID 参数写入驱动 %1 的 ROM？
%2</translation>
    </message>
    <message>
        <source>ROM is the drive&apos;s flash memory: each write wears it, and the gains stay after power-off. Try them in RAM first; write to ROM once you are satisfied. Each loop is sent once with 0x44 (never retried), then all gains are read back with 0x40.</source>
        <translation>ROM 是驱动的闪存：每次写入都会造成磨损，且参数在断电后仍然保留。请先在 RAM 中试用，满意后再写入 ROM。每个环用 0x44 只发送一次（绝不重试），然后用 0x40 回读全部参数。</translation>
    </message>
    <message>
        <source>Write to ROM</source>
        <translation>写入 ROM</translation>
    </message>
    <message>
        <source>Written to the ROM of drive %1 (0x44, acknowledged) and read back with 0x40: the drive holds what was sent.</source>
        <translation>已写入驱动 %1 的 ROM（0x44，已确认）并用 0x40 回读：驱动保存的就是发送的值。</translation>
    </message>
    <message>
        <source>Written to the RAM of drive %1 and read back: the drive holds what was sent. Lost at power-off unless written to ROM.</source>
        <translation>已写入驱动 %1 的 RAM 并回读：驱动保存的就是发送的值。除非写入 ROM，否则断电丢失。</translation>
    </message>
</context>
<context>
    <name>lk::ui::TuningText</name>
    <message>
        <source>Write gains to ROM</source>
        <translation>写入 PID 参数到 ROM</translation>
    </message>
    <message>
        <source>Write these PID gains to the ROM of drive %1?
%2 (angle, speed, iq Kp/Ki)</source>
        <translation>将这些 PID 参数写入驱动 %1 的 ROM？
%2（角度、速度、iq 的 Kp/Ki）</translation>
    </message>
    <message>
        <source>ROM is the drive&apos;s flash memory: each write wears it, and the gains stay after power-off. Try them in RAM first; write to ROM once you are satisfied. Acceleration is written to RAM only (V2.3 has no ROM command for it). Afterwards the gains are read back from RAM; V2.3 has no command that reads ROM, so the ROM copy itself cannot be checked.</source>
        <translation>ROM 是驱动的闪存：每次写入都会磨损，参数断电后仍保留。请先在 RAM 中试用，满意后再写入 ROM。加速度只写入 RAM（V2.3 没有对应的 ROM 命令）。写入后会从 RAM 回读 PID 参数；V2.3 没有读取 ROM 的命令，因此无法核对 ROM 中的副本本身。</translation>
    </message>
    <message>
        <source>Write to ROM</source>
        <translation>写入 ROM</translation>
    </message>
    <message>
        <source>Restore values read at %1</source>
        <translation>恢复 %1 读取的值</translation>
    </message>
    <message>
        <source>Write to RAM</source>
        <translation>写入 RAM</translation>
    </message>
    <message>
        <source>RAM holds gains %1 after %2 was written to ROM: either the write did not land or this drive takes ROM values into RAM only at power-on. V2.3 cannot read ROM, so which of the two is not known.</source>
        <translation>将 %2 写入 ROM 后，RAM 中的参数为 %1：要么写入未生效，要么此驱动仅在上电时把 ROM 值载入 RAM。V2.3 无法读取 ROM，因此无法判断是哪一种。</translation>
    </message>
    <message>
        <source>The drive holds gains %1 after %2 was written.</source>
        <translation>写入 %2 后，驱动保存的参数为 %1。</translation>
    </message>
    <message>
        <source>The read-back did not complete: what the drive holds is not known. Editing and writing stay off until Read from drive succeeds.</source>
        <translation>回读未完成：驱动实际保存的值未知。在“从驱动读取”成功之前，编辑和写入保持禁用。</translation>
    </message>
    <message>
        <source>Written to the ROM of drive %1. Verified: the gains read back from RAM equal what was sent. Not verifiable: this drive generation (V2.3) cannot read ROM; the drive loads the ROM values at the next power-on, and only a read after that shows them. Acceleration went to RAM only.</source>
        <translation>已写入驱动 %1 的 ROM。已核实：从 RAM 回读的 PID 参数与发送的一致。无法核实：此代驱动（V2.3）无法读取 ROM；驱动在下次上电时载入 ROM 中的值，只有之后的读取才能显示它们。加速度只写入了 RAM。</translation>
    </message>
    <message>
        <source>Written to the RAM of drive %1 and read back: the drive holds what was sent. Lost at power-off unless written to ROM.</source>
        <translation>已写入驱动 %1 的 RAM 并回读：驱动保存的就是发送的值。除非写入 ROM，否则断电丢失。</translation>
    </message>
    <message>
        <source>Gains %1 (angle, speed, iq Kp/Ki), acceleration %2 dps/s.</source>
        <translation>参数 %1（角度、速度、iq 的 Kp/Ki），加速度 %2 dps/s。</translation>
    </message>
    <message>
        <source>Write the values first read from drive %1 at %2 to its RAM now?
%3</source>
        <translation>现在将 %2 首次从驱动 %1 读取的数值写入其 RAM？
%3</translation>
    </message>
    <message>
        <source>This writes to the drive: the values in its RAM are replaced at once, and so is your pending edit. ROM is not touched; RAM is lost at power-off.</source>
        <translation>这会写入驱动：其 RAM 中的值会立即被替换，你的待写入修改也会被替换。ROM 不受影响；RAM 断电丢失。</translation>
    </message>
    <message>
        <source>The drive reports acceleration %1 dps/s after %2 dps/s was written: some firmware ignores 0x34 or reads 0 with 0x33 (see docs/ERRATA.md), so the acceleration in effect is not known.</source>
        <translation>写入 %2 dps/s 后，驱动报告的加速度为 %1 dps/s：部分固件忽略 0x34 或用 0x33 读出 0（见 docs/ERRATA.md），因此实际生效的加速度未知。</translation>
    </message>
    <message>
        <source>CAN V2.36 keeps these in RAM only: they are lost at power-off. The drive has no command to store its control parameters (0xC0/0xC1) in ROM, so this view has no &quot;Write to ROM&quot; button.</source>
        <translation>CAN V2.36 只把这些参数保存在 RAM 中：断电后即丢失。驱动器没有把控制参数（0xC0/0xC1）存入 ROM 的命令，因此本视图没有“写入 ROM”按钮。</translation>
    </message>
</context>
<context>
    <name>lk::ui::TuningView</name>
    <message>
        <source>PID gains and acceleration</source>
        <translation>PID 参数和加速度</translation>
    </message>
    <message>
        <source>Gains go to RAM (try: lost at power-off) or ROM (keep). Acceleration is RAM only: protocol V2.3 has no command that stores it.</source>
        <translation>参数可写入 RAM（试用：断电丢失）或 ROM（保存）。加速度只能写入 RAM：协议 V2.3 没有保存它的命令。</translation>
    </message>
    <message>
        <source>Read from drive</source>
        <translation>从驱动读取</translation>
    </message>
    <message>
        <source>read_pid (0x30) and read_accel (0x33)</source>
        <translation>read_pid (0x30) 和 read_accel (0x33)</translation>
    </message>
    <message>
        <source>Write to RAM</source>
        <translation>写入 RAM</translation>
    </message>
    <message>
        <source>Try the pending edit: 0x31 and 0x34, lost at power-off; read back.</source>
        <translation>试用待写入的值：0x31 和 0x34，断电丢失；随后回读。</translation>
    </message>
    <message>
        <source>Write to ROM…</source>
        <translation>写入 ROM…</translation>
    </message>
    <message>
        <source>Keep the gains: 0x32 writes flash (asks first); read back.</source>
        <translation>保存参数：0x32 写入闪存（会先询问）；随后回读。</translation>
    </message>
    <message>
        <source>Save to file…</source>
        <translation>保存到文件…</translation>
    </message>
    <message>
        <source>Save what the drive holds, with model, firmware and time, as JSON.</source>
        <translation>把驱动当前的参数连同型号、固件和时间保存为 JSON。</translation>
    </message>
    <message>
        <source>Load from file…</source>
        <translation>从文件加载…</translation>
    </message>
    <message>
        <source>Save drive parameters</source>
        <translation>保存驱动参数</translation>
    </message>
    <message>
        <source>Parameter files (*.json)</source>
        <translation>参数文件 (*.json)</translation>
    </message>
    <message>
        <source>Load drive parameters</source>
        <translation>加载驱动参数</translation>
    </message>
    <message>
        <source>RAM and ROM: %1</source>
        <translation>RAM 和 ROM：%1</translation>
    </message>
    <message>
        <source>Load a parameter file into the pending edit; nothing is written. Needs a complete read of the drive first.</source>
        <translation>把参数文件载入待写入区；不会写入任何值。需要先完整读取驱动。</translation>
    </message>
    <message>
        <source>Disconnected: the values shown are the last ones read. Tuning resumes after the drive has been read again on the next connection.</source>
        <translation>已断开：显示的是最后读取的数值。重新连接并再次读取驱动后才能继续调参。</translation>
    </message>
    <message>
        <source>Restore values read at %1…</source>
        <translation>恢复 %1 读取的值…</translation>
    </message>
    <message>
        <source>Restore values first read…</source>
        <translation>恢复首次读取的值…</translation>
    </message>
    <message>
        <source>Writes the values of the first complete read of this drive on this connection back to its RAM (asks first).</source>
        <translation>把本次连接中首次完整读取此驱动得到的值写回其 RAM（会先询问）。</translation>
    </message>
    <message>
        <source>PID gains</source>
        <translation>PID 参数</translation>
    </message>
    <message>
        <source>Drive limits</source>
        <translation>驱动限值</translation>
    </message>
    <message>
        <source>Write the values first read from this drive at %1 back to its RAM (asks first), then read back.</source>
        <translation>将 %1 首次从此驱动读取的数值写回其 RAM（会先询问），然后回读。</translation>
    </message>
    <message>
        <source>Nothing was loaded: a file is loaded against the drive&apos;s values, so read the drive&apos;s values first.</source>
        <translation>未加载任何内容：文件是对照驱动的数值加载的，请先读取驱动的数值。</translation>
    </message>
    <message>
        <source>Live plot</source>
        <translation>实时曲线</translation>
    </message>
    <message>
        <source>Step response</source>
        <translation>阶跃响应</translation>
    </message>
    <message>
        <source>Repeat step test</source>
        <translation>重复阶跃测试</translation>
    </message>
    <message>
        <source>Run the last step test again with the gains the drive holds now, and compare it with the runs before (Step response tab).</source>
        <translation>用驱动当前的参数再次执行上次的阶跃测试，并与之前的测试比较（阶跃响应页）。</translation>
    </message>
    <message>
        <source>ROM write</source>
        <translation>写入 ROM</translation>
    </message>
    <message>
        <source>RAM write</source>
        <translation>写入 RAM</translation>
    </message>
    <message>
        <source>Frequency response</source>
        <translation>频率响应</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>%1 is not plugged in: showing the built-in simulated bus. Pick the port and press Connect when the adapter is in.</source>
        <translation>%1 未插上：显示内置模拟总线。转换器插好后，请选择串口并点击“连接”。</translation>
    </message>
    <message>
        <source>The simulated drives move on their own (a demo) so that the plots show live values. Command any drive, or press Esc, and the demo stops.</source>
        <translation>模拟驱动正在自行运动（演示），以便曲线显示实时数值。对任一驱动发出命令或按 Esc，演示即停止。</translation>
    </message>
</context>
</TS>
