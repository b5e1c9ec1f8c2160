// Shadertoy's inputs, declared before a Shadertoy shader's own code.
uniform vec3 iResolution;
uniform float iTime;
uniform float iTimeDelta;
uniform float iFrameRate;
uniform int iFrame;
uniform vec4 iMouse;
uniform vec4 iDate;
uniform float iSampleRate;
uniform float iChannelTime[4];
uniform vec3 iChannelResolution[4];
uniform sampler2D iChannel0;
uniform sampler2D iChannel1;
uniform sampler2D iChannel2;
uniform sampler2D iChannel3;
// The camera of foveate's built-in scenes (from the camera path).
uniform vec3 foveate_cam_pos;
uniform vec3 foveate_cam_target;
uniform float foveate_cam_fov;
