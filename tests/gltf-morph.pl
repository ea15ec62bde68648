#!/usr/bin/perl
# gltf-morph.pl [STRIDE [LENGTH]] -- print a small glTF 2.0 file: one triangle with
# one morph target and a 3-key animation of its weight, the weights stored
# as normalized uint8 (the accessor mesh-import decodes itself).  STRIDE,
# when given, is written as the weights' bufferView byteStride verbatim
# (tests of the accessor bounds check), and LENGTH as its byteLength
# (the buffer is padded with zeros to hold it).
use strict;
use warnings;
use MIME::Base64;
my $stride = shift;
my $wlen = shift // 3;
my $b = '';
$b .= pack('f<9', 0,0,0, 1,0,0, 0,1,0);          # positions, offset 0
$b .= pack('v3x2', 0, 1, 2);                     # indices, offset 36
$b .= pack('f<9', 0,0,1, 0,0,1, 0,0,1);          # target deltas, offset 44
$b .= pack('f<3', 0, 0.5, 1);                    # key times, offset 80
$b .= pack("C3", 0, 255, 128);                    # weights, offset 92
$b .= "\0" x ($wlen + 1 - 3);
my $blen = length $b;
my $uri = 'data:application/octet-stream;base64,' . encode_base64($b, '');
my $ws = defined $stride ? qq(, "byteStride": $stride) : '';
print <<"END";
{
 "asset": {"version": "2.0"},
 "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"name": "tri", "mesh": 0}],
 "meshes": [{"name": "tri", "weights": [0],
   "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "targets": [{"POSITION": 2}]}]}],
 "animations": [{"name": "wave", "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}],
   "samplers": [{"input": 3, "output": 4, "interpolation": "LINEAR"}]}],
 "buffers": [{"byteLength": $blen, "uri": "$uri"}],
 "bufferViews": [
   {"buffer": 0, "byteOffset": 0, "byteLength": 36},
   {"buffer": 0, "byteOffset": 36, "byteLength": 6},
   {"buffer": 0, "byteOffset": 44, "byteLength": 36},
   {"buffer": 0, "byteOffset": 80, "byteLength": 12},
   {"buffer": 0, "byteOffset": 92, "byteLength": $wlen$ws}],
 "accessors": [
   {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
   {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
   {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,1], "max": [0,0,1]},
   {"bufferView": 3, "componentType": 5126, "count": 3, "type": "SCALAR", "min": [0], "max": [1]},
   {"bufferView": 4, "componentType": 5121, "normalized": true, "count": 3, "type": "SCALAR"}]
}
END
