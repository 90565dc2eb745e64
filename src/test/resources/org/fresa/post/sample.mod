MODULE example_2
  ! Fresa robot program for irb140: 4 motions
  PERS tooldata tFresa1 := [TRUE,[[0.000,0.000,0.000],[1.00000000,0.00000000,0.00000000,0.00000000]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata wFresa := [FALSE,TRUE,"",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  ! the joints and poses are in the robot base frame (wFresa is the identity); each tooldata
  ! is a tool's TCP in the flange frame (spindle and tool length), as Fresa solved it

  PROC main()
    ConfJ \On;
    ConfL \On;
    ! workingstep approach
    MoveAbsJ [[0.000000,10.000000,-20.000000,0.000000,55.500000,0.000000],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],[250.000,500,5000,1000],fine,tFresa1\WObj:=wFresa; ! 0
    ! workingstep WS 1
    MoveL [[500.000,10.000,350.000],[0.00000000,0.00000000,1.00000000,0.00000000],[-1,2,-2,1],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],[5.000,500,5000,1000],fine,tFresa1\WObj:=wFresa; ! j=[-1.250000,12.500000,-22.123457,181.000000,-35.250000,-91.000000] ! 1
    MoveL [[520.000,10.000,350.000],[0.00000000,0.25881905,0.96592583,0.00000000],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],[5.000,500,5000,1000],[FALSE,0.500,0.750,0.750,0.15,0.750,0.15],tFresa1\WObj:=wFresa; ! j=[2.500000,13.000000,-21.000000,0.000000,30.000000,0.100000] ! 2
    ! workingstep WS 2
    MoveL [[540.000,10.250,350.000],[0.00000000,0.00000000,1.00000000,0.00000000],[0,-1,3,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]],[8.500,500,5000,1000],[FALSE,0.500,0.750,0.750,0.15,0.750,0.15],tFresa1\WObj:=wFresa; ! j=[3.000000,13.500000,-20.500000,-0.500000,31.000000,359.900000] ! 3
  ENDPROC
ENDMODULE
