#!/usr/bin/perl
# merge-copies.pl N SHIFT < plain.mesh > merged.mesh: N copies of an animation
# side by side (x offset 1.2 widths), copy i running SHIFT*i frames ahead (mod
# the frame count) so that the copies move differently; for page-size tests.
use strict; use warnings;
my ($n, $shift) = @ARGV;
my ($nv, $nf, $nfr, @F, @X, $k);
while (<STDIN>) {
    if (/^vertices (\d+)/) { $nv = $1 } elsif (/^faces (\d+)/) { $nf = $1 }
    elsif (/^frames (\d+)/) { $nfr = $1 } elsif (/^f (.*)/) { push @F, [split ' ', $1] }
    elsif (/^frame (\d+)/) { $k = $1; $X[$k] = [] } elsif (/^MESH/) { }
    else { push @{$X[$k]}, [split] }
}
my ($lo, $hi) = (1e300, -1e300);
for (@{$X[0]}) { $lo = $_->[0] if $_->[0] < $lo; $hi = $_->[0] if $_->[0] > $hi }
my $w = 1.2 * ($hi - $lo);
print "MESH 1\nvertices ", $n * $nv, "\nfaces ", $n * $nf, "\nframes $nfr\n";
for my $i (0 .. $n - 1) { my $o = $i * $nv; print "f ", join(' ', map { $_ + $o } @$_), "\n" for @F }
for my $k (0 .. $nfr - 1) {
    print "frame $k\n";
    for my $i (0 .. $n - 1) {
        my $s = ($k + $i * $shift) % $nfr, my $dx = $i * $w;
        print $_->[0] + $dx, " $_->[1] $_->[2]\n" for @{$X[$s]};
    }
}
